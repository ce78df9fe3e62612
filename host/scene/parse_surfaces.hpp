#pragma once
// Readers of the surface object types: "bezier" (patch sets, inline or from a patch file),
// "parametric" (equations in u and v), "implicit" (an equation f(x, y, z) = 0), "mesh" (a
// triangle mesh file) and "spheres" (a PLY point set). Registered in
// shape_readers() (parse_shapes.cpp).
#include <functional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"
#include "surface/closed_surface.hpp"

namespace lancer {

Shape read_bezier(TableReader& t, const glm::dmat4& to_world);
Shape read_parametric(TableReader& t, const glm::dmat4& to_world);
Shape read_implicit(TableReader& t, const glm::dmat4& to_world);
Shape read_mesh(TableReader& t, const glm::dmat4& to_world);  // parse_mesh.cpp
Shape read_spheres(TableReader& t, const glm::dmat4& to_world);  // parse_spheres.cpp: a sphere set
// POV-Ray's superellipsoid, a shape of its own (parse_superellipsoid.cpp).
Shape read_superellipsoid(TableReader& t, const glm::dmat4& to_world);
Shape read_blob(TableReader& t, const glm::dmat4& to_world);  // parse_blob.cpp: POV-Ray's blob
Shape read_sor(TableReader& t, const glm::dmat4& to_world);   // parse_sor.cpp: POV-Ray's surface of revolution
Shape read_text(TableReader& t, const glm::dmat4& to_world);  // parse_text.cpp: POV-Ray's text, a prism
// The frame text is built in: its prism's outline is in x-z and extrudes along y; this mirror (y
// and z swapped) makes it POV-Ray's text (glyphs in x-y, extruded along +z). read_object uses it.
glm::dmat4 text_frame();
Shape read_prism(TableReader& t, const glm::dmat4& to_world); // parse_prism.cpp: POV-Ray's prism
Shape read_lathe(TableReader& t, const glm::dmat4& to_world); // parse_lathe.cpp: POV-Ray's lathe

// Where in the scene file a column of f's text is: inside the `function` string, or the key
// whose values the function was written from.
using ColumnPlace = std::function<SourceLocation(int column)>;

// The checks and preparation of every implicit surface (parse_implicit.cpp), once f and the box
// are in `object`: errors at `key` (and within f's text, at `place`), then placed by `to_world`.
Shape prepared_implicit(TableReader& t, ImplicitObject object, const std::string& key, const ColumnPlace& place,
                        const glm::dmat4& to_world);

// Whether objects of this type are implicit surfaces (counted against the implicit limits).
bool is_implicit_type(std::string_view type);

// Fails at `key` unless every coordinate of [lo, hi] is within kMaxMagnitude: geometry built by
// transforms and equations must stay as representable as the numbers it came from.
void check_world_extent(TableReader& t, std::string_view key, const dvec3& lo, const dvec3& hi);

// A surface declared `closed = true`: the side its normals face (surface::outward_side), or a
// failure at `closed` saying why the samples show no solid.
int outward_side_of_declared(TableReader& t, const std::vector<surface::SampledPatch>& samples);

}  // namespace lancer

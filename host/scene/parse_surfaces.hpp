#pragma once
// Readers of the surface object types: "bezier" (patch sets, inline or from a patch file),
// "parametric" (equations in u and v), "implicit" (an equation f(x, y, z) = 0) and "mesh" (a
// triangle mesh file). Registered in
// shape_readers() (parse_shapes.cpp).
#include <glm/mat4x4.hpp>

#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

Shape read_bezier(TableReader& t, const glm::dmat4& to_world);
Shape read_parametric(TableReader& t, const glm::dmat4& to_world);
Shape read_implicit(TableReader& t, const glm::dmat4& to_world);
Shape read_mesh(TableReader& t, const glm::dmat4& to_world);  // parse_mesh.cpp

// Fails at `key` unless every coordinate of [lo, hi] is within kMaxMagnitude: geometry built by
// transforms and equations must stay as representable as the numbers it came from.
void check_world_extent(TableReader& t, std::string_view key, const dvec3& lo, const dvec3& hi);

}  // namespace lancer

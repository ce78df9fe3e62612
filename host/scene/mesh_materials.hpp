#pragma once
// A mesh file's own materials (an OBJ's MTL: Kd, Ks, Ns, d, map_Kd) as the scene's: for a mesh
// object without a material of its own, nor from its group or placement (docs/scene-format.md,
// "Meshes"); and a point set's colours, on its object's material ("Sphere sets").
#include <cstdint>
#include <vector>

#include "scene/parse_material_maps.hpp"
#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

// Appends a Material for each of the mesh file's materials to scene.materials and returns their
// indices, in the file's order. Errors (a texture that cannot be read, too many materials) are
// SceneErrors at the object's `file`.
std::vector<std::uint32_t> add_mesh_materials(const MeshGeometry& geometry, const TableReader& t, Scene& scene,
                                              TextureLibrary& textures);

// Appends, for each colour of a point set's palette, a copy of material `base` whose colour is
// that one (its checker, were it one, gone: the point's colour is the pigment's), and returns
// their indices in the palette's order. Too many materials is a SceneError at the object's `file`.
std::vector<std::uint32_t> add_point_colors(const SphereCloud& cloud, std::uint32_t base, const TableReader& t, Scene& scene);

}  // namespace lancer

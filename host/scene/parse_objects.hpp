#pragma once
// The [[object]] entries (docs/scene-format.md, "[[object]]"): shapes; groups, flattened into
// their members; declared objects ([declare.NAME]) placed by `type = "object"`; CSG objects.
// Each object gets its placement from its transform after its groups' (scene/placement.hpp).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "scene/parse_material_maps.hpp"
#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

using MaterialIndex = std::map<std::string, std::uint32_t, std::less<>>;  // material name -> index
// Reads a [material.NAME]-like table (load_scene.cpp's reader): an object's own material.
using MaterialReader = std::function<Material(TableReader& table, const std::string& name)>;

// What an object's `material` may be: a name of the scene's, or a table of its own (added to
// scene.materials).
struct MaterialChoice {
    const MaterialIndex& named;
    const MaterialReader& read_inline;
    Scene& scene;
};

// Reads the scene's [[object]] entries into scene.objects (objects without a material, and
// members of groups without one, take default_material). Entry i made the objects
// [starts[i], starts[i + 1]) of the returned starts: what [animation] moves by its name.
std::vector<std::size_t> read_objects(TableReader& top, const MaterialIndex& named, const MaterialReader& read_inline,
                                      std::uint32_t default_material, Scene& scene, TextureLibrary& textures);

}  // namespace lancer

#pragma once
// The [[object]] entries (docs/scene-format.md, "[[object]]"): shapes; groups, flattened into
// their members; declared objects ([declare.NAME]) placed by `type = "object"`; CSG objects.
// Each object gets its placement from its transform after its groups' (scene/placement.hpp).
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "scene/parse_material_maps.hpp"
#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

using MaterialIndex = std::map<std::string, std::uint32_t, std::less<>>;  // material name -> index

// Reads the scene's [[object]] entries into scene.objects (objects without a material, and
// members of groups without one, take default_material). Entry i made the objects
// [starts[i], starts[i + 1]) of the returned starts: what [animation] moves by its name.
std::vector<std::size_t> read_objects(TableReader& top, const MaterialIndex& materials, std::uint32_t default_material,
                                      Scene& scene, TextureLibrary& textures);

}  // namespace lancer

#pragma once
// The [[object]] entries (docs/scene-format.md, "[[object]]"): shapes; groups, flattened into
// their members; declared objects ([declare.NAME]) placed by `type = "object"`; CSG objects.
// Each object gets its placement from its transform after its groups' (scene/placement.hpp).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
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

// Reads [[object]] entries into scene.objects (objects without a material, and members of
// groups without one, take default_material): a scene's whole array, or its batches one after
// another (object_batches.hpp), numbered on across them. The scene-wide counts and the
// materials added for mesh files and point colours carry over from batch to batch.
class ObjectEntries {
public:
    // `top` is the scene's root table, for its [declare] tables.
    ObjectEntries(TableReader& top, const MaterialIndex& named, const MaterialReader& read_inline,
                  std::uint32_t default_material, Scene& scene, TextureLibrary& textures);
    ~ObjectEntries();
    ObjectEntries(const ObjectEntries&) = delete;
    ObjectEntries& operator=(const ObjectEntries&) = delete;

    void read(const toml::array& entries, const FileName& file);
    // Room in scene.objects for `entries` more objects (one an entry, groups aside).
    void reserve(std::size_t entries);
    // Entry i made the objects [starts[i], starts[i + 1]): what [animation] moves by its name.
    const std::vector<std::size_t>& starts() const { return starts_; }

private:
    struct Reading;
    MaterialChoice materials_;
    std::unique_ptr<Reading> reading_;
    std::vector<std::size_t> starts_{0};
};

}  // namespace lancer

#pragma once
// The `texture`, `pattern` and `bump` keys of a [material.NAME] table (docs/scene-format.md,
// "Textures and patterns"): their keys, defaults and checks in one place.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace lancer {

// The scene's texture images: each file is read once however many materials use it, and the
// limits on sizes and counts (scene/limits.hpp) are checked from the files' headers before any
// image is decoded.
class TextureLibrary {
public:
    // Files read are appended to `dependencies` (Scene::dependencies).
    explicit TextureLibrary(std::vector<std::string>& dependencies) : dependencies_(dependencies) {}

    // The image at `path` (`name` as the scene writes it, resolved against the scene's
    // directory). Errors are SceneErrors at the value of `key` in `t`, naming `name`.
    std::shared_ptr<const TextureImage> load(const TableReader& t, std::string_view key, const std::string& name,
                                             const std::string& path);

private:
    std::vector<std::string>& dependencies_;
    std::map<std::string, std::shared_ptr<const TextureImage>> images_;
    long long texels_ = 0;
};

// A colour ramp: `colors` (2 to kMaxPatternColors) and optional `stops` (ascending, in [0, 1]).
std::vector<ColorStop> read_ramp(TableReader& t);

// The keys a colour pattern, a bump and the sky's pattern share: type, placement and the
// turbulence sum (the ramp is read apart).
Pattern read_pattern_shape(TableReader& t);

// Reads the material's optional `texture`, `pattern` and `bump` keys into `m`.
void read_material_maps(TableReader& t, Material& m, TextureLibrary& textures);

// The plane's texture axes (Plane::u_axis, v_axis) for its unit normal.
void set_plane_texture_axes(Plane& plane);

}  // namespace lancer

#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "scene/object_batches.hpp"
#include "scene/scene.hpp"
#include "scene/scene_values.hpp"

namespace lancer {

// Reads and validates a TOML scene file, its expressions at `time` (scene_values.hpp). Every
// problem is a SceneError at file:line:col; an unreadable file is a UserError.
Scene load_scene(const std::string& path, SceneTime time = {});

// How parse_scene reads the TOML: the whole document as one tree, or its head (all but its
// [[object]] tables) and then its objects in batches, one batch's tree at a time
// (object_batches.hpp). Both give the same Scene and the same errors: a file the batches cannot
// be sure to read alike, and any error, is read whole.
enum class TomlReading { Whole, Batches };

// The same from text already in memory; `path` is used for messages only.
Scene parse_scene(std::string_view text, const std::string& path, SceneTime time = {},
                  TomlReading reading = TomlReading::Batches);

// The reading in batches alone, without the whole parse behind it: any error is thrown as it
// is found (which error comes first may differ from the whole parse's). For tests.
Scene parse_scene_batches(std::string_view text, const SceneTextParts& parts, const std::string& path, SceneTime time = {});

// Photon mapping's settings where a scene gives none ([photons] keys left out, or --photons on
// a scene without the table): radii scaled to the distance from the camera to what it looks at.
PhotonSettings photon_defaults(const CameraSpec& camera);

// Why adaptive anti-aliasing cannot run as these settings ask ("" when it can); `depth_given`
// and `method_given`: whether aa_depth and aa_method were set, which means nothing without
// aa_threshold. The scene loader reports it at the key, the command line after its overrides.
struct SettingProblem {
    std::string key;  // the [render] key at fault
    std::string message;
};
std::optional<SettingProblem> adaptive_settings_problem(const RenderSettings& r, bool depth_given, bool method_given);

}  // namespace lancer

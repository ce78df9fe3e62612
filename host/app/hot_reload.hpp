#pragma once
// What `lancer watch` and `lancer view` share about reloading: which shader directory to compile
// and watch, the scene at --frame, and which files make up the scene: its file and the files it
// references (Scene::dependencies: patch files, textures, ...). An edit to any of them reloads
// the scene; every other file the watcher reports is a shader.
#include <filesystem>
#include <optional>
#include <set>
#include <string>

#include "app/file_watcher.hpp"
#include "app/render_options.hpp"
#include "core/error.hpp"
#include "scene/scene.hpp"

namespace lancer {

// --shaders (which must be a directory), else ./shaders when it holds the tracer (running from
// the repository), else "": the built-in shaders are used and only the scene is watched.
std::string resolve_shader_dir(const std::string& given);

// The static scene to show: the file with the command line's overrides, at `frame` (default 0)
// of its animation. --frame for a scene without [animation] is an error.
Scene load_scene_at_frame(const RenderOptions& options, std::optional<int> frame);

// Keeps `watcher` on the files of the scene last loaded. Until a scene loads, that is the scene
// file alone. A scene that fails to load adds only the file its error is in.
class SceneFiles {
public:
    SceneFiles(FileWatcher& watcher, const std::string& scene_file);

    // After each successful load: watch the scene file and `scene.dependencies`, and stop
    // watching files it no longer references.
    void watch(const Scene& scene);
    // After a failed load: also watch the file the error points into when it is not one already
    // watched (a broken patch file that the edited scene has just begun to reference), so that
    // fixing that file reloads the scene.
    void watch_failure(const UserError& error);
    // Whether a path the watcher reported is one of the scene's files.
    bool contains(const std::filesystem::path& changed) const { return files_.count(changed) > 0; }
    // How many files the scene references besides itself.
    std::size_t references() const { return files_.size() - 1; }

private:
    void replace(std::set<std::filesystem::path> files);

    FileWatcher& watcher_;
    std::string scene_file_;
    std::set<std::filesystem::path> files_;  // FileWatcher::identity() of each
};

// A burst of changed files, sorted into what has to be redone.
struct Changes {
    bool scene = false;    // the scene file or a file it references
    bool shaders = false;  // anything else the watcher reports: files under the shader directory
    std::string names;     // "scene.toml, teapot.bpt": the changed files' names, for messages
};
Changes classify(const std::set<std::filesystem::path>& changed, const SceneFiles& scene_files);

}  // namespace lancer

#include "app/hot_reload.hpp"

#include <fmt/format.h>

#include "scene/animation.hpp"

namespace lancer {
namespace fs = std::filesystem;

std::string resolve_shader_dir(const std::string& given) {
    if (!given.empty()) {
        if (!fs::is_directory(given)) throw UserError("--shaders: '" + given + "' is not a directory");
        return given;
    }
    return fs::exists("shaders/trace.comp") ? "shaders" : "";
}

Scene load_scene_at_frame(const RenderOptions& options, std::optional<int> frame) {
    Scene loaded = load_scene_with_overrides(options);
    if (loaded.animation) {
        int n = loaded.animation->frames;
        int f = frame.value_or(0);
        if (f < 0 || f >= n) throw UserError(fmt::format("--frame {} is outside the animation's frames 0-{}", f, n - 1));
        return scene_for_frame(options, loaded, f);
    }
    if (frame) throw UserError("--frame: the scene has no [animation]");
    return loaded;
}

SceneFiles::SceneFiles(FileWatcher& watcher, const std::string& scene_file)
    : watcher_(watcher), scene_file_(scene_file) {
    files_ = {FileWatcher::identity(scene_file_)};
    watcher_.watch_files(files_);
}

void SceneFiles::watch(const Scene& scene) {
    std::set<fs::path> files = {FileWatcher::identity(scene_file_)};
    for (const std::string& d : scene.dependencies) files.insert(FileWatcher::identity(d));
    replace(std::move(files));
}

void SceneFiles::watch_failure(const UserError& error) {
    const auto* located = dynamic_cast<const SceneError*>(&error);
    if (!located || located->where().file.empty() || !fs::is_regular_file(located->where().file.str())) return;
    std::set<fs::path> files = files_;
    files.insert(FileWatcher::identity(located->where().file.str()));
    replace(std::move(files));
}

void SceneFiles::replace(std::set<fs::path> files) {
    if (files == files_) return;
    watcher_.watch_files(files);
    files_ = std::move(files);
}

Changes classify(const std::set<fs::path>& changed, const SceneFiles& scene_files) {
    Changes c;
    for (const auto& p : changed) {
        (scene_files.contains(p) ? c.scene : c.shaders) = true;
        c.names += (c.names.empty() ? "" : ", ") + p.filename().string();
    }
    return c;
}

}  // namespace lancer

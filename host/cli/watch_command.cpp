// `lancer watch`: render, then re-render whenever the shaders or the scene change. The loop for
// people who work on the renderer itself: a shader edit recompiles the tracer at run time (the
// glslang library, the same sources and defines as the embedded SPIR-V) and rebuilds only the
// pipeline; a scene edit only re-uploads the scene. Errors are printed and the last good
// pipeline, scene and image are kept.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/file_watcher.hpp"
#include "cli/render_options.hpp"
#include "gpu/context.hpp"
#include "gpu/gpu_renderer.hpp"
#include "gpu/shader_compiler.hpp"
#include "scene/animation.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Everything a reload line reports: "scene.toml changed: compiled in 143 ms, rendered in 210 ms".
std::string describe_changes(const std::set<fs::path>& changed) {
    std::string names;
    for (const auto& p : changed) names += (names.empty() ? "" : ", ") + p.filename().string();
    return names + " changed";
}

struct WatchCommand {
    RenderOptions options;  // options.shader_dir: the directory to watch
    std::optional<int> frame;  // of an animated scene

    // The shader directory to watch: --shaders, else ./shaders when it exists (running from the
    // repository), else none (only the scene is watched; the embedded shaders are used).
    std::string resolve_shader_dir() const {
        if (!options.shader_dir.empty()) {
            if (!fs::is_directory(options.shader_dir))
                throw UserError("--shaders: '" + options.shader_dir + "' is not a directory");
            return options.shader_dir;
        }
        if (fs::exists("shaders/trace.comp")) return "shaders";
        return "";
    }

    int run() {
        std::string output = output_path(options);
        check_output_writable(output);
        std::string shaders = resolve_shader_dir();
        FileWatcher watcher;  // also turns Ctrl-C into a clean exit
        RenderOptions without_shaders = options;
        without_shaders.shader_dir.clear();  // compiled below, where errors are kept, not fatal
        auto renderer = make_renderer(without_shaders);
        auto* gpu = dynamic_cast<GpuRenderer*>(renderer.get());
        if (!shaders.empty() && !gpu) throw UserError("--shaders needs the gpu backend");

        if (!shaders.empty()) watcher.watch_tree(shaders, {".comp", ".glsl", ".h"});
        watcher.watch_file(options.scene);

        std::optional<Scene> scene;
        auto load = [&]() -> bool {
            try {
                Scene loaded = load_scene_with_overrides(options);
                if (loaded.animation) {
                    int n = loaded.animation->frames;
                    int f = frame.value_or(0);
                    if (f < 0 || f >= n)
                        throw UserError(fmt::format("--frame {} is outside the animation's frames 0-{}", f, n - 1));
                    loaded = scene_at(loaded, frame_time(*loaded.animation, f));
                } else if (frame) {
                    throw UserError("--frame: the scene has no [animation]");
                }
                scene = std::move(loaded);
                // The scene's own files (patch files, textures) reload it too.
                std::vector<fs::path> files{options.scene};
                files.insert(files.end(), scene->dependencies.begin(), scene->dependencies.end());
                watcher.set_files(files);
                return true;
            } catch (const UserError& e) {
                std::fprintf(stderr, "%s\n", format_error(e).c_str());
                return false;
            }
        };
        auto compile = [&](double& ms) -> bool {
            auto start = Clock::now();
            try {
                gpu->use_shaders(gpu::directory_tree(shaders), shaders);
                ms = ms_since(start);
                return true;
            } catch (const gpu::ShaderCompileError& e) {
                std::fprintf(stderr, "%s\n", e.what());
                return false;
            }
        };
        auto render = [&](double& ms) -> bool {
            auto start = Clock::now();
            try {
                FloatImage image = renderer->render(*scene, [&](double) { return !watcher.signal_pending(); });
                write_png(output, to_srgb8(image));
                ms = ms_since(start);
                return true;
            } catch (const RenderCancelled&) {
                return false;
            }
        };

        double compile_ms = 0.0, render_ms = 0.0;
        bool compiled = shaders.empty() || compile(compile_ms);
        bool loaded = load();
        if (loaded && render(render_ms))
            std::fprintf(stderr, "watch: %s -> %s (compiled in %.0f ms, rendered in %.0f ms); watching %s%s\n",
                         options.scene.c_str(), output.c_str(), compile_ms, render_ms,
                         shaders.empty() ? "" : (shaders + "/ and ").c_str(), options.scene.c_str());
        (void)compiled;

        for (;;) {
            FileWatcher::Result wake = watcher.wait(std::chrono::milliseconds(100));
            if (wake.wake == FileWatcher::Wake::Signal) break;
            bool shader_changed = false, scene_changed = false;
            for (const auto& p : wake.changed) (watcher.is_watched_file(p) ? scene_changed : shader_changed) = true;
            std::string what = describe_changes(wake.changed);
            compile_ms = 0.0;
            if (shader_changed && !compile(compile_ms)) {
                std::fprintf(stderr, "reload: %s: compile failed, keeping the last good shaders and image\n", what.c_str());
                continue;
            }
            if (scene_changed && !load()) {
                std::fprintf(stderr, "reload: %s: scene error, keeping the last good scene and image\n", what.c_str());
                continue;
            }
            if (!scene) continue;  // no good scene yet
            if (!render(render_ms)) break;  // interrupted
            std::fprintf(stderr, "reload: %s: compiled in %.0f ms, rendered in %.0f ms -> %s\n", what.c_str(), compile_ms,
                         render_ms, output.c_str());
        }
        renderer.reset();  // every Vulkan object released before the validation count
        if (std::uint32_t n = gpu::validation_message_count()) {
            std::fprintf(stderr, "lancer: error: %u Vulkan validation message(s)\n", n);
            return 1;
        }
        return 0;
    }
};

}  // namespace

Subcommand add_watch_command(CLI::App& parent) {
    auto state = std::make_shared<WatchCommand>();
    CLI::App* cmd = parent.add_subcommand("watch", "Render, then re-render whenever the shaders or the scene change");
    add_render_options(*cmd, state->options);
    cmd->get_option("--shaders")
        ->description("Shader directory to compile and watch (default: ./shaders if present, else the built-in shaders)");
    cmd->add_option("--frame", state->frame, "Frame of an animated scene to preview (default 0)");
    return {cmd, [state] { return state->run(); }};
}

}  // namespace lancer

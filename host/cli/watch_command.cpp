// `lancer watch`: render, then re-render whenever the shaders or the scene change. The loop for
// people who work on the renderer itself: a shader edit recompiles the tracer at run time (the
// glslang library, the same sources and defines as the embedded SPIR-V) and rebuilds only the
// pipeline; an edit of the scene or of a file it references only reloads and re-uploads the
// scene. Errors are printed and the last good pipeline and scene are kept.
#include <chrono>
#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "app/file_watcher.hpp"
#include "app/hot_reload.hpp"
#include "app/option_checks.hpp"
#include "app/render_options.hpp"
#include "core/cancel.hpp"
#include "gpu/vulkan/context.hpp"
#include "gpu/shaders/shader_compiler.hpp"

namespace lancer {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// One reload line's parts, in order: "compiled in 143 ms", "scene reloaded", "rendered in ...".
void append(std::string& line, const std::string& part) { line += (line.empty() ? "" : "; ") + part; }

struct WatchCommand {
    RenderOptions options;  // options.shader_dir: the directory to watch
    std::optional<int> frame;  // of an animated scene

    int run() {
        std::string output = output_path(options);
        check_output_writable(output);
        FileWatcher watcher;  // also turns Ctrl-C into a clean exit
        RenderOptions without_shaders = options;
        without_shaders.shader_dir.clear();  // compiled below, where errors are kept, not fatal
        auto renderer = make_renderer(without_shaders);
        const bool gpu = renderer->runs_shaders();
        if (!gpu && !options.shader_dir.empty()) throw UserError("--shaders needs the gpu backend");
        const std::string shaders = gpu ? resolve_shader_dir(options.shader_dir) : "";

        if (!shaders.empty()) watcher.watch_tree(shaders, {".comp", ".glsl", ".h"});
        SceneFiles scene_files(watcher, options.scene);

        std::optional<Scene> scene;
        auto load = [&]() -> bool {
            try {
                Scene loaded = load_scene_at_frame(options, frame);
                scene_files.watch(loaded);
                scene = std::move(loaded);
                return true;
            } catch (const UserError& e) {
                print_error(e);
                scene_files.watch_failure(e);
                return false;
            } catch (const Cancelled&) {
                return false;  // Ctrl-C while loading: the loop below sees it and ends
            }
        };
        // On failure the renderer keeps the shaders it had: the last good ones, or the built-in ones.
        auto compile = [&](double& ms) -> bool {
            auto start = Clock::now();
            try {
                renderer->use_shader_directory(shaders);
                ms = ms_since(start);
                return true;
            } catch (const gpu::ShaderCompileError& e) {
                std::fprintf(stderr, "%s\n", e.what());
                return false;
            } catch (const Cancelled&) {
                return false;
            }
        };
        auto render = [&](double& ms) -> bool {
            auto start = Clock::now();
            try {
                FloatImage image = renderer->render(*scene, [&](double) { return !watcher.signal_pending(); });
                write_image(output, image, image_info(*scene));
                ms = ms_since(start);
                return true;
            } catch (const RenderCancelled&) {
                return false;
            }
        };

        double compile_ms = 0.0, render_ms = 0.0;
        std::string first;
        bool compiled = false;
        if (gpu && !shaders.empty()) {
            compiled = compile(compile_ms);
            if (!compiled && watcher.signal_pending()) return finish(std::move(renderer));  // Ctrl-C while compiling
        }
        if (!gpu) {
            append(first, "cpu backend");
        } else if (shaders.empty()) {
            append(first, "built-in shaders");
        } else if (compiled) {
            append(first, fmt::format("{}/ compiled in {:.0f} ms", shaders, compile_ms));
        } else {
            std::fprintf(stderr, "watch: %s/ does not compile; using the built-in shaders until it does\n", shaders.c_str());
            append(first, fmt::format("built-in shaders until {}/ compiles", shaders));
        }
        if (!load()) {
            if (watcher.signal_pending()) return finish(std::move(renderer));
            append(first, "no image until the scene loads");
        } else {
            if (!render(render_ms)) return finish(std::move(renderer));  // interrupted
            append(first, fmt::format("rendered in {:.0f} ms -> {}", render_ms, output));
        }
        std::string referenced = scene_files.references() == 0 ? ""
                                 : fmt::format(" and the {} file(s) it references", scene_files.references());
        std::fprintf(stderr, "watch: %s (%s); watching %s%s%s\n", options.scene.c_str(), first.c_str(),
                     shaders.empty() ? "" : (shaders + "/ and ").c_str(), options.scene.c_str(), referenced.c_str());

        // A burst may change shaders and scene together: each is reloaded on its own, and
        // whatever succeeded is rendered with whatever is good of the other (a scene edit shows
        // even while the shaders are broken, with the last good ones), so the image is always
        // the newest that works and a later fix of either starts from the other's latest state.
        for (;;) {
            FileWatcher::Result wake = watcher.wait(std::chrono::milliseconds(100));
            if (wake.wake == FileWatcher::Wake::Signal) break;
            Changes changes = classify(wake.changed, scene_files);
            std::string line;
            bool renew = false;
            if (changes.shaders) {
                bool ok = compile(compile_ms);
                append(line, ok ? fmt::format("compiled in {:.0f} ms", compile_ms) : "compile failed, keeping the last good shaders");
                renew |= ok;
            }
            if (changes.scene) {
                bool ok = load();
                append(line, ok ? "scene reloaded" : "scene error, keeping the last good scene");
                renew |= ok;
            }
            if (!scene) {
                append(line, "no image until the scene loads");
            } else if (!renew) {
                append(line, "image unchanged");
            } else {
                if (!render(render_ms)) break;  // interrupted
                append(line, fmt::format("rendered in {:.0f} ms -> {}", render_ms, output));
            }
            std::fprintf(stderr, "reload: %s changed: %s\n", changes.names.c_str(), line.c_str());
        }
        return finish(std::move(renderer));
    }

    static int finish(std::unique_ptr<Renderer> renderer) {
        renderer.reset();  // every Vulkan object released before the validation count
        return gpu::exit_code_after_validation(0);
    }
};

}  // namespace

Subcommand add_watch_command(CLI::App& parent) {
    auto state = std::make_shared<WatchCommand>();
    CLI::App* cmd = parent.add_subcommand("watch", "Render, then re-render whenever the shaders or the scene change");
    add_render_options(*cmd, state->options);
    cmd->get_option("--shaders")
        ->description("Shader directory to compile and watch (default: ./shaders if present, else the built-in shaders)");
    cmd->add_option("--frame", state->frame, "Frame of an animated scene to preview (default 0)")->transform(decimal_integer());
    return {cmd, [state] { return state->run(); }};
}

}  // namespace lancer

#include "view/viewer.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <set>
#include <thread>

#include <SDL.h>
#include <fmt/format.h>

#include "app/option_checks.hpp"
#include "app/file_watcher.hpp"
#include "app/frame_pattern.hpp"
#include "app/hot_reload.hpp"
#include "app/video.hpp"
#include "gpu/vulkan/context.hpp"
#include "gpu/gpu_renderer.hpp"
#include "view/camera_controller.hpp"
#include "view/frame_stats.hpp"
#include "view/recordings.hpp"
#include "view/render_worker.hpp"
#include "view/sdl_display.hpp"
#include "view/status_text.hpp"

namespace lancer::view {
namespace {

namespace fs = std::filesystem;

std::optional<CameraMove> camera_move_for(SDL_Keycode key) {
    switch (key) {
        case SDLK_RIGHT: return CameraMove::Right;
        case SDLK_LEFT: return CameraMove::Left;
        case SDLK_UP: return CameraMove::Up;
        case SDLK_DOWN: return CameraMove::Down;
        case SDLK_q: return CameraMove::OrbitLeft;
        case SDLK_d: return CameraMove::OrbitRight;
        case SDLK_w: return CameraMove::RollLeft;
        case SDLK_x: return CameraMove::RollRight;
        // '+' is a key of its own on some layouts, shift+'=' on others, and on the keypad.
        case SDLK_PLUS: case SDLK_EQUALS: case SDLK_KP_PLUS: return CameraMove::DollyIn;
        case SDLK_MINUS: case SDLK_KP_MINUS: return CameraMove::DollyOut;
        default: return std::nullopt;
    }
}

// Runs FileWatcher::wait() on a thread of its own and turns what it reports into SDL events;
// stops (and is joined) when destroyed.
class WatchThread {
public:
    WatchThread(FileWatcher& watcher, std::uint32_t files_event) : watcher_(watcher), thread_([this, files_event] {
        for (;;) {
            FileWatcher::Result r = watcher_.wait(std::chrono::milliseconds(100));
            SDL_Event e{};
            if (r.wake == FileWatcher::Wake::Interrupted) return;
            if (r.wake == FileWatcher::Wake::Signal) {  // Ctrl-C or SIGTERM: quit cleanly
                e.type = SDL_QUIT;
                SDL_PushEvent(&e);
                return;
            }
            {
                std::lock_guard lock(mutex_);
                changed_.insert(r.changed.begin(), r.changed.end());
            }
            e.type = files_event;
            SDL_PushEvent(&e);
        }
    }) {}
    ~WatchThread() {
        watcher_.interrupt();
        thread_.join();
    }
    std::set<fs::path> take_changes() {
        std::lock_guard lock(mutex_);
        return std::exchange(changed_, {});
    }

private:
    FileWatcher& watcher_;
    std::mutex mutex_;
    std::set<fs::path> changed_;
    std::thread thread_;
};

class Viewer {
public:
    explicit Viewer(const ViewerOptions& options)
        : options_(options),
          shader_dir_(resolve_shader_dir(options.render.shader_dir)),
          scene_(load_scene_at_frame(options.render, options.frame)),
          controller_(scene_.camera),
          scene_name_(fs::path(options.render.scene).filename().string()),
          stem_(fs::path(options.render.scene).stem().string()) {
        if (options.render.backend != "gpu") throw UserError("lancer view renders on the GPU only (no --backend cpu)");
        // -o names the PNGs `p` saves: checked now rather than when the user presses p.
        std::string first = snapshot_path(false);
        if (image_format_of(first) != ImageFormat::Png)
            throw UserError("-o " + options.render.output + ": p saves PNG images, so the name must end in .png");
        check_output_writable(first);
        check_output_is_not_an_input(first, scene_inputs(scene_));
        if (!options.dump_frame.empty()) check_output_writable(options.dump_frame);
    }

    int run(FileWatcher& watcher) {
        auto renderer = std::make_unique<GpuRenderer>(
            gpu::ContextOptions{options_.render.device, gpu::validation_requested_by_environment()});
        if (!shader_dir_.empty()) {
            try {
                renderer->use_shaders(gpu::directory_tree(shader_dir_), shader_dir_);
            } catch (const gpu::ShaderCompileError& e) {
                std::fprintf(stderr, "%s\nview: %s/ does not compile; using the built-in shaders until it does\n", e.what(),
                             shader_dir_.c_str());
            }
            watcher.watch_tree(shader_dir_, {".comp", ".glsl", ".h"});
        }
        scene_files_.emplace(watcher, options_.render.scene);
        scene_files_->watch(scene_);
        std::string device = renderer->description();

        SdlDisplay display("lancer view: " + scene_name_, scene_.render.width, scene_.render.height);
        display_ = &display;
        const std::uint32_t first_event = SDL_RegisterEvents(2);
        if (first_event == std::uint32_t(-1)) throw std::runtime_error("SDL_RegisterEvents failed");
        const std::uint32_t frame_event = first_event, files_event = first_event + 1;
        RenderWorker worker(std::move(renderer), [frame_event] {
            SDL_Event e{};
            e.type = frame_event;
            SDL_PushEvent(&e);
        });
        worker_ = &worker;
        WatchThread watch_thread(watcher, files_event);
        say(fmt::format("view: {} {}x{}, {} rays/pixel, {}; window: SDL renderer '{}'; press h for the keys",
                        options_.render.scene, scene_.render.width, scene_.render.height,
                        scene_.render.samples * scene_.render.samples, device, display.renderer_name()));

        generation_ = worker.show(view_scene(), false);
        while (!quit_) {
            SDL_Event e;
            if (!SDL_WaitEvent(&e)) throw std::runtime_error(std::string("SDL_WaitEvent: ") + SDL_GetError());
            // All events waiting, then one new view for all the moves among them.
            do {
                if (e.type == files_event) {
                    reload(watch_thread.take_changes());
                } else if (e.type != frame_event) {
                    moved_ |= handle(e);
                }
            } while (!quit_ && SDL_PollEvent(&e));
            if (std::exception_ptr failure = worker.failed()) std::rethrow_exception(failure);
            if (quit_) break;
            show_moves();
            if (std::optional<ShownFrame> frame = worker.take_frame()) present(*frame);
            else if (redraw_) repaint();
        }
        say(stats_.summary(display.renderer_name()));
        return 0;
    }

private:
    Scene view_scene() const {
        Scene s = scene_;
        s.camera = controller_.camera();
        return s;
    }

    // Hands the camera moves handled so far to the worker: at the end of each batch of events,
    // and before a request (p) that must see them.
    void show_moves() {
        if (!moved_) return;
        moved_ = false;
        generation_ = worker_->show(view_scene(), true);
        if (!waiting_since_) waiting_since_ = {std::chrono::steady_clock::now(), generation_};
    }

    void say(const std::string& line) const {
        if (!options_.render.quiet) std::fprintf(stderr, "%s\n", line.c_str());
    }

    // -o: a name (overwritten by each p), or a pattern with a frame number (the first unused,
    // and never one handed out before, since saves are written later); by default
    // NAME-view-001.png, NAME-view-002.png, ...
    std::string snapshot_path(bool take) {
        std::string text = options_.render.output.empty() ? stem_ + "-view-%03d.png" : options_.render.output;
        std::optional<FramePattern> pattern = FramePattern::parse(text);
        if (!pattern) return text;
        for (int k = snapshot_number_ + 1;; ++k)
            if (!fs::exists(pattern->path(k))) {
                if (take) snapshot_number_ = k;
                return pattern->path(k);
            }
    }

    // Returns true when the camera moved.
    bool handle(const SDL_Event& e) {
        switch (e.type) {
            case SDL_QUIT: quit_ = true; return false;
            case SDL_WINDOWEVENT: redraw_ = true; return false;
            case SDL_KEYDOWN: return key(e.key.keysym.sym);
            case SDL_MOUSEMOTION:
                if (!(e.motion.state & SDL_BUTTON_LMASK) || !camera_free()) return false;
                controller_.drag(e.motion.xrel, e.motion.yrel);
                return true;
            case SDL_MOUSEWHEEL: {
                int notches = e.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e.wheel.y : e.wheel.y;
                if (notches == 0 || !camera_free()) return false;
                controller_.wheel(notches);
                return true;
            }
            default: return false;
        }
    }

    // While a sequence records, the window shows its frames and the camera waits.
    bool camera_free() {
        if (!worker_->recording()) return true;
        if (!told_recording_) say("view: recording; the camera stays until it ends (f or l stops it, Esc quits)");
        told_recording_ = true;
        return false;
    }

    bool key(SDL_Keycode k) {
        if (std::optional<CameraMove> move = camera_move_for(k)) {
            if (!camera_free()) return false;
            controller_.move(*move);
            return true;
        }
        switch (k) {
            case SDLK_ESCAPE: quit_ = true; return false;
            case SDLK_r:
                if (!camera_free()) return false;
                controller_.reset();
                return true;
            case SDLK_h:
                display_->toggle_help();
                redraw_ = true;
                return false;
            case SDLK_p:
                show_moves();
                worker_->save(snapshot_path(true));
                return false;
            case SDLK_f: record("orbit"); return false;
            case SDLK_l: record("light"); return false;
            default: return false;
        }
    }

    void record(const std::string& kind) {
        if (worker_->recording()) {
            worker_->cancel_recording();
            return;
        }
        try {
            int frames = options_.record_frames;
            Scene animated = kind == "orbit" ? orbit_recording(scene_, controller_.camera(), frames)
                                             : light_recording(scene_, controller_.camera(), frames);
            std::string name = next_recording_name("", stem_, kind);
            RecordingJob job{kind, std::move(animated), name + "/frame_" + frame_field(frames) + ".png", ""};
            if (!find_program("ffmpeg").empty()) job.video = name + ".mp4";
            else say("view: ffmpeg is not installed: recording frames only, no video");
            told_recording_ = false;
            worker_->record(std::move(job));
        } catch (const UserError& e) {
            print_error(e);
        }
    }

    // Shaders and scene are reloaded independently: a scene edit in the same burst as a broken
    // shader still shows, drawn with the last good shaders.
    void reload(const std::set<fs::path>& changed) {
        Changes changes = classify(changed, *scene_files_);
        if (changes.shaders && !shader_dir_.empty()) {
            say("reload: " + changes.names + " changed: compiling");
            worker_->reload_shaders(shader_dir_);
        }
        if (!changes.scene) return;
        try {
            Scene loaded = load_scene_at_frame(options_.render, options_.frame);
            scene_files_->watch(loaded);
            scene_ = std::move(loaded);
            controller_.set_home(scene_.camera);
            display_->set_image_size(scene_.render.width, scene_.render.height);
            generation_ = worker_->show(view_scene(), false);
            say("reload: " + changes.names + " changed: scene reloaded");
        } catch (const UserError& e) {
            print_error(e);
            scene_files_->watch_failure(e);
            std::fprintf(stderr, "reload: %s changed: scene error, keeping the last good scene and picture\n",
                         changes.names.c_str());
        }
    }

    void present(const ShownFrame& frame) {
        // Never back in time: a picture of a view older than the one on screen would flicker
        // back. A preview of a view the user has just left is still the nearest there is.
        if (frame.kind != ShownFrame::Kind::Recording && frame.generation < shown_generation_) return;
        if (frame.kind != ShownFrame::Kind::Recording) shown_generation_ = frame.generation;
        switch (frame.kind) {
            case ShownFrame::Kind::Preview: stats_.preview(frame.render_ms, frame.preview_divisor); break;
            case ShownFrame::Kind::Final: stats_.refinement(frame.view_ms); [[fallthrough]];
            case ShownFrame::Kind::Pass:
                stats_.pass(frame.render_ms);
                stats_.convert(frame.convert_ms);
                break;
            case ShownFrame::Kind::Recording: break;
        }
        display_->show(frame.image);
        stats_.upload(display_->last_upload_ms());
        if (waiting_since_ && frame.generation >= waiting_since_->generation) {
            stats_.response(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - waiting_since_->time).count());
            waiting_since_.reset();
        }
        const bool finished = frame.kind == ShownFrame::Kind::Final && frame.generation == generation_;
        if (finished && !options_.dump_frame.empty()) {
            display_->draw();
            write_png(options_.dump_frame, display_->read_pixels());
        }
        auto start = std::chrono::steady_clock::now();
        display_->draw();
        display_->present();
        stats_.present(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        if (finished) say(refined_line(frame));
        display_->set_title(window_title(scene_name_, frame));
        redraw_ = false;
    }

    void repaint() {
        display_->draw();
        display_->present();
        redraw_ = false;
    }

    ViewerOptions options_;
    std::string shader_dir_;
    Scene scene_;  // static, as loaded: the camera comes from controller_
    std::optional<SceneFiles> scene_files_;  // from run(): the files watched as the scene's
    CameraController controller_;
    std::string scene_name_, stem_;
    SdlDisplay* display_ = nullptr;
    RenderWorker* worker_ = nullptr;
    std::uint64_t generation_ = 0;        // the view asked for last
    std::uint64_t shown_generation_ = 0;  // the view of the picture on screen
    bool quit_ = false;
    bool moved_ = false;  // the camera moved since the worker was last told
    bool redraw_ = false;
    bool told_recording_ = false;
    int snapshot_number_ = 0;  // the last one handed out
    FrameStats stats_;
    // The first camera move not yet on screen: how long the window takes to answer.
    struct Waiting {
        std::chrono::steady_clock::time_point time;
        std::uint64_t generation;
    };
    std::optional<Waiting> waiting_since_;
};

}  // namespace

int run_viewer(const ViewerOptions& options) {
    // First, so SIGINT/SIGTERM are blocked before the driver, SDL or the viewer start threads
    // (they inherit the mask) and arrive through the watcher as a clean quit.
    FileWatcher watcher;
    {
        Viewer viewer(options);
        viewer.run(watcher);
    }  // worker joined, every Vulkan object released, window closed
    return gpu::exit_code_after_validation(0);
}

}  // namespace lancer::view

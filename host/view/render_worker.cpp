#include "view/render_worker.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "app/frame_pattern.hpp"
#include "app/video.hpp"
#include "core/cancel.hpp"
#include "gpu/shaders/shader_compiler.hpp"
#include "scene/animation.hpp"
#include "view/camera_text.hpp"
#include "view/recordings.hpp"
#include "view/refinement.hpp"

namespace lancer::view {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Previews aim at this many milliseconds, so holding a key or dragging feels immediate.
constexpr double kPreviewBudgetMs = 30.0;
constexpr int kMaxPreviewDivisor = 16;
constexpr std::chrono::milliseconds kSettle{60};

// The parts of a picture's description that come from its scene.
ShownFrame describe(const Scene& scene, std::uint64_t generation) {
    ShownFrame f;
    f.generation = generation;
    f.camera = scene.camera;
    f.width = scene.render.width;
    f.height = scene.render.height;
    f.samples = scene.render.samples;
    return f;
}

// Samples per GPU dispatch: a camera move waits for the dispatch in flight, so a few tens of
// milliseconds of work each (lavapipe traces a few Mrays/s per core, ~5 rays a sample in
// scenes/seed.toml); each submit costs ~0.2 ms.
constexpr std::size_t kDispatchSamples = 64 * 1024;

std::unique_ptr<GpuRenderer> with_small_dispatches(std::unique_ptr<GpuRenderer> renderer) {
    renderer->set_max_dispatch_samples(kDispatchSamples);
    return renderer;
}

}  // namespace

RenderWorker::RenderWorker(std::unique_ptr<GpuRenderer> renderer, std::function<void()> wake)
    : renderer_(with_small_dispatches(std::move(renderer))), wake_(std::move(wake)), thread_([this] { run(); }) {}

RenderWorker::~RenderWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    changed_.notify_all();
    thread_.join();
    renderer_.reset();  // every Vulkan object, before the caller counts validation messages
}

std::uint64_t RenderWorker::show(const Scene& scene, bool moving) {
    std::lock_guard lock(mutex_);
    scene_ = scene;
    moving_ = moving;
    ++generation_;
    changed_.notify_all();
    return generation_;
}

void RenderWorker::reload_shaders(const std::string& shader_dir) {
    std::lock_guard lock(mutex_);
    reload_ = shader_dir;
    changed_.notify_all();
}

void RenderWorker::save(const std::string& path) {
    std::lock_guard lock(mutex_);
    if (!scene_) return;
    saves_.push_back({path, *scene_, generation_});
    changed_.notify_all();
}

void RenderWorker::record(RecordingJob job) {
    std::lock_guard lock(mutex_);
    recording_ = std::move(job);
    cancel_recording_ = false;
    changed_.notify_all();
}

void RenderWorker::cancel_recording() {
    std::lock_guard lock(mutex_);
    cancel_recording_ = true;
}

bool RenderWorker::recording() const {
    std::lock_guard lock(mutex_);
    return recording_.has_value();
}

std::optional<ShownFrame> RenderWorker::take_frame() {
    std::lock_guard lock(mutex_);
    return std::exchange(frame_, std::nullopt);
}

std::exception_ptr RenderWorker::failed() const {
    std::lock_guard lock(mutex_);
    return failure_;
}

void RenderWorker::publish(ShownFrame frame) {
    {
        std::lock_guard lock(mutex_);
        frame_ = std::move(frame);
    }
    wake_();
}

bool RenderWorker::still_wanted(std::uint64_t generation) const {
    std::lock_guard lock(mutex_);
    return wanted_locked(generation);
}

bool RenderWorker::wanted_locked(std::uint64_t generation) const {
    if (stop_ || generation_ != generation || reload_ || (recording_ && !recording_active_)) return false;
    // A save of this very view waits for the refinement to finish; a save of another one cannot.
    for (const SaveJob& s : saves_)
        if (s.generation != generation) return false;
    return true;
}

void RenderWorker::run() {
    for (;;) {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] {
            return stop_ || reload_ || (recording_ && !recording_active_) || !saves_.empty() ||
                   (scene_ && refined_ != generation_);
        });
        if (stop_) return;
        try {
            if (reload_) {
                std::string dir = *std::exchange(reload_, std::nullopt);
                std::uint64_t refined = std::exchange(refined_, 0);  // the view is drawn again with the new code
                lock.unlock();
                if (!run_reload(dir)) {
                    // Nothing new to draw, unless a new view (a reloaded scene) came meanwhile.
                    lock.lock();
                    refined_ = refined;
                }
            } else if (recording_ && !recording_active_) {
                recording_active_ = true;
                RecordingJob job = *recording_;
                lock.unlock();
                run_recording(job);
                lock.lock();
                recording_.reset();
                recording_active_ = false;
                refined_ = 0;  // back to the interactive view
            } else if (!saves_.empty()) {
                SaveJob job = std::move(saves_.front());
                saves_.pop_front();
                lock.unlock();
                run_save(job);
            } else {
                Scene scene = *scene_;
                std::uint64_t generation = generation_;
                bool moving = std::exchange(moving_, false);
                lock.unlock();
                refine(scene, generation, moving);
            }
        } catch (const RenderCancelled&) {
            // Something newer was asked for; the loop picks it up.
        } catch (...) {
            // Not the user's doing (a Vulkan call failed): the viewer stops and reports it.
            if (!lock.owns_lock()) lock.lock();
            failure_ = std::current_exception();
            lock.unlock();
            wake_();
            return;
        }
    }
}

void RenderWorker::refine(const Scene& scene, std::uint64_t generation, bool moving) {
    auto wanted = [&](double) { return still_wanted(generation); };
    if (moving) {
        auto start = Clock::now();
        // Not cancelled by newer moves: a preview is short, and the one of the move before is
        // still a better picture than none while the camera keeps moving.
        FloatImage preview = renderer_->render(preview_scene(scene, preview_divisor_), [&](double) {
            std::lock_guard lock(mutex_);
            return !stop_;
        });
        ShownFrame f = describe(scene, generation);
        f.kind = ShownFrame::Kind::Preview;
        auto convert_start = Clock::now();
        f.image = to_srgb8(preview, scene.render.tone);
        f.convert_ms = ms_since(convert_start);
        f.preview_divisor = preview_divisor_;
        f.render_ms = ms_since(start);
        f.rays = preview.total_rays();
        preview_divisor_ = next_preview_divisor(preview_divisor_, f.render_ms, kPreviewBudgetMs, kMaxPreviewDivisor);
        publish(std::move(f));
        // While the camera keeps moving (a held key repeats every ~30-50 ms, a drag reports every
        // frame), the next move comes soon: starting a pass now would make its preview wait for
        // the dispatch in flight. Refinement starts once the camera has been still this long.
        std::unique_lock lock(mutex_);
        if (changed_.wait_for(lock, kSettle, [&] { return !wanted_locked(generation); })) throw RenderCancelled();
    }

    if (scene.render.aa_threshold && !scene.photons) {
        refine_adaptive(scene, generation);
        return;
    }
    const std::uint32_t total = refinement_total(scene);
    auto view_start = Clock::now();
    FloatImage sums;
    double rays_before = 0.0;
    const std::vector<SamplePass> passes = refinement_plan(scene);
    for (std::size_t p = 0; p < passes.size(); ++p) {
        auto start = Clock::now();
        renderer_->render_samples(scene, passes[p].first, passes[p].count, sums, wanted);
        ShownFrame f = describe(scene, generation);
        f.samples_done = passes[p].first + passes[p].count;
        f.pass = int(p) + 1;
        f.passes = int(passes.size());
        f.kind = f.samples_done == total ? ShownFrame::Kind::Final : ShownFrame::Kind::Pass;
        f.render_ms = ms_since(start);
        const std::uint32_t samples_done = f.samples_done;
        publish_pass(std::move(f), sums, samples_done, scene.render.tone, view_start, rays_before);
    }
}

void RenderWorker::publish_pass(ShownFrame f, const FloatImage& sums, std::uint32_t samples_done,
                                const ToneMapping& tone, std::chrono::steady_clock::time_point view_start,
                                double& rays_before) {
    const bool final_pass = f.kind == ShownFrame::Kind::Final;
    // A first pass is one sample at full size: what a preview at 1/d of each side costs d^2 less.
    if (f.pass == 1) preview_divisor_ = preview_divisor_for(f.render_ms, kPreviewBudgetMs, kMaxPreviewDivisor);
    auto convert_start = Clock::now();
    f.image = display_image(sums, samples_done, final_pass, tone);
    f.convert_ms = ms_since(convert_start);
    f.view_ms = ms_since(view_start);
    f.view_rays = sums.total_rays();
    f.rays = f.view_rays - rays_before;
    rays_before = f.view_rays;
    if (final_pass) {
        std::lock_guard lock(mutex_);
        refined_ = f.generation;
        refined_image_ = f.image;
    }
    publish(std::move(f));
}

// Adaptive anti-aliasing: its steps as passes, each picture as it comes (the first ray of every
// pixel, then each refinement); the last is the picture `lancer render` makes.
void RenderWorker::refine_adaptive(const Scene& scene, std::uint64_t generation) {
    auto view_start = Clock::now(), start = view_start;
    double rays_before = 0.0;
    renderer_->render_in_steps(
        scene, [&](double) { return still_wanted(generation); },
        [&](const FloatImage& image, int step, int steps, bool final_pass) {
            ShownFrame f = describe(scene, generation);
            f.kind = final_pass ? ShownFrame::Kind::Final : ShownFrame::Kind::Pass;
            f.pass = step + 1;
            f.passes = final_pass ? step + 1 : steps + 1;
            f.refined_pixels = image.refined_pixels;
            f.camera_rays = image.camera_rays;
            f.render_ms = ms_since(start);
            // Its pixels are means already: nothing to divide.
            publish_pass(std::move(f), image, 1, scene.render.tone, view_start, rays_before);
            start = Clock::now();
        });
}

void RenderWorker::run_save(const SaveJob& job) {
    Rgb8Image image;
    {
        std::lock_guard lock(mutex_);
        if (refined_ == job.generation && refined_image_) image = *refined_image_;
    }
    if (image.bytes.empty()) {
        // Not refined yet (or a view the user has left): the same picture, in one go.
        image = to_srgb8(renderer_->render(job.scene, [&](double) {
            std::lock_guard lock(mutex_);
            return !stop_;
        }), job.scene.render.tone);
    }
    try {
        write_png(job.path, image);
    } catch (const UserError& e) {
        print_error(e);  // an unwritable directory, a full disk: the viewer goes on
        return;
    }
    const RenderSettings& r = job.scene.render;
    std::fprintf(stderr, "view: saved %s (%dx%d, %d rays/pixel); camera: %s\n", job.path.c_str(), r.width, r.height,
                 r.samples * r.samples, camera_toml(job.scene.camera).c_str());
}

bool RenderWorker::run_reload(const std::string& shader_dir) {
    auto start = Clock::now();
    try {
        renderer_->use_shaders(gpu::directory_tree(shader_dir), shader_dir);
        std::fprintf(stderr, "reload: shaders compiled in %.0f ms\n", ms_since(start));
        return true;
    } catch (const gpu::ShaderCompileError& e) {
        std::fprintf(stderr, "%s\nreload: compile failed, keeping the last good shaders\n", e.what());
        return false;
    } catch (const Cancelled&) {
        return false;  // SIGINT or SIGTERM: the viewer is quitting
    }
}

void RenderWorker::run_recording(const RecordingJob& job) {
    const Animation& animation = *job.scene.animation;
    auto cancelled = [&] {
        std::lock_guard lock(mutex_);
        return stop_ || cancel_recording_;
    };
    int done = 0;
    std::string directory;
    try {
        std::optional<FramePattern> pattern = FramePattern::parse(job.pattern);
        directory = pattern->directory();
        std::fprintf(stderr, "view: recording %s to %s: %s\n", job.kind.c_str(), job.pattern.c_str(),
                     describe_recording(animation).c_str());
        std::error_code ec;
        if (!directory.empty()) std::filesystem::create_directories(directory, ec);
        if (ec) throw UserError(fmt::format("cannot create the frame directory '{}': {}", directory, ec.message()));
        auto start = Clock::now();
        for (int k = 0; k < animation.frames; ++k) {
            auto frame_start = Clock::now();
            Scene frame = scene_at(job.scene, frame_time(animation, k));
            FloatImage image = renderer_->render(frame, [&](double) { return !cancelled(); });
            ShownFrame f = describe(frame, 0);
            f.kind = ShownFrame::Kind::Recording;
            f.image = to_srgb8(image, frame.render.tone);
            write_png(pattern->path(k), f.image);
            ++done;
            f.render_ms = ms_since(frame_start);
            f.rays = image.total_rays();
            f.status = fmt::format("recording {}: frame {}/{}", job.kind, k + 1, animation.frames);
            publish(std::move(f));
        }
        double seconds = ms_since(start) / 1000.0;
        std::string video;
        if (!job.video.empty()) {
            make_video(job.pattern, animation.frames, animation.fps, job.video);
            video = ", video " + job.video;
        }
        std::fprintf(stderr, "view: recorded %s: %d frames in %.1f s (%.2f s/frame) to %s%s\n", job.kind.c_str(),
                     animation.frames, seconds, seconds / animation.frames, job.pattern.c_str(), video.c_str());
    } catch (const RenderCancelled&) {
        std::fprintf(stderr, "view: recording %s stopped after %d of %d frames (in %s)\n", job.kind.c_str(), done,
                     animation.frames, directory.c_str());
    } catch (const UserError& e) {
        print_error(e);
        std::fprintf(stderr, "view: recording %s failed after %d of %d frames\n", job.kind.c_str(), done, animation.frames);
    }
}

}  // namespace lancer::view

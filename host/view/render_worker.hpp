#pragma once
// The viewer's renderer on a thread of its own, so the window never waits for the GPU. The event
// loop tells it what to show (and to save, record, reload); each new view cancels the work in
// progress (GpuRenderer checks between bands), shows a fast preview if the camera is moving, then
// refines pass by pass up to the scene's full anti-aliasing. Finished pictures are handed back
// through take_frame(), newest first: the window only ever wants the latest.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "gpu/gpu_renderer.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"
#include "view/shown_frame.hpp"

namespace lancer::view {

struct RecordingJob {
    std::string kind;        // "orbit", "light": for messages
    Scene scene;             // animated (view/recordings.hpp)
    std::string pattern;     // frame pattern, e.g. seed-orbit-1/frame_%03d.png
    std::string video;       // "" for frames only
};

class RenderWorker {
public:
    // `wake` is called from the worker thread whenever take_frame() or failed() has news (the
    // viewer turns it into an SDL event, which is thread-safe).
    RenderWorker(std::unique_ptr<GpuRenderer> renderer, std::function<void()> wake);
    ~RenderWorker();  // cancels, joins the thread, then releases every Vulkan object
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    // A new picture to show: a static scene at its full resolution and samples. `moving`: the
    // camera just moved, so a preview comes first. Returns the view's generation.
    std::uint64_t show(const Scene& scene, bool moving);
    // Recompile the tracer from `shader_dir` (on the worker: the renderer is not shared), then
    // refine the current view again. Compile errors are printed; the last good shaders stay.
    void reload_shaders(const std::string& shader_dir);
    // Write the current view at full quality to `path` (a PNG), now if it is refined already.
    void save(const std::string& path);
    // Render every frame of the job's animation to its pattern, then the video; the window shows
    // each frame as it is written. Views asked for meanwhile wait until it ends or is cancelled.
    void record(RecordingJob job);
    void cancel_recording();
    bool recording() const;

    std::optional<ShownFrame> take_frame();
    // An internal failure on the worker (a Vulkan call failed): the viewer should stop and
    // rethrow it. Null while all is well.
    std::exception_ptr failed() const;

private:
    struct SaveJob {
        std::string path;
        Scene scene;
        std::uint64_t generation;
    };
    void run();
    void refine(const Scene& scene, std::uint64_t generation, bool moving);
    void refine_adaptive(const Scene& scene, std::uint64_t generation);
    // Publishes a pass of a refinement (`f` with its kind, pass and render time): the picture of
    // `sums` (divided by `samples_done` unless it is the final one), the time and rays since
    // the refinement began at `view_start`, and for the final one the picture p saves.
    void publish_pass(ShownFrame f, const FloatImage& sums, std::uint32_t samples_done, const ToneMapping& tone,
                      std::chrono::steady_clock::time_point view_start, double& rays_before);
    void run_save(const SaveJob& job);
    void run_recording(const RecordingJob& job);
    bool run_reload(const std::string& shader_dir);  // false: did not compile
    void publish(ShownFrame frame);
    // For the renderer's progress callback: true while nothing newer has been asked for.
    bool still_wanted(std::uint64_t generation) const;
    bool wanted_locked(std::uint64_t generation) const;  // mutex_ held

    std::unique_ptr<GpuRenderer> renderer_;
    std::function<void()> wake_;

    mutable std::mutex mutex_;
    std::condition_variable changed_;
    bool stop_ = false;
    std::optional<Scene> scene_;        // the view asked for
    std::uint64_t generation_ = 0;      // of scene_
    bool moving_ = false;
    std::uint64_t refined_ = 0;         // generation whose refinement is complete (0: none)
    std::optional<Rgb8Image> refined_image_;
    std::deque<SaveJob> saves_;
    std::optional<std::string> reload_;
    std::optional<RecordingJob> recording_;
    bool recording_active_ = false;
    bool cancel_recording_ = false;
    std::optional<ShownFrame> frame_;   // the newest picture, not yet taken
    std::exception_ptr failure_;
    int preview_divisor_ = 2;           // adapted to keep previews fast (worker thread only)

    std::thread thread_;  // last: starts after everything above exists
};

}  // namespace lancer::view

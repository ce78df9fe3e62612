#include "cli/animation_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numeric>
#include <vector>

#include <fmt/format.h>

#include "app/frame_pattern.hpp"
#include "app/interrupt.hpp"
#include "app/option_checks.hpp"
#include "cli/progress.hpp"
#include "cli/still_render.hpp"
#include "app/video.hpp"
#include "gpu/vulkan/context.hpp"
#include "image/image.hpp"
#include "render/adaptive_render.hpp"
#include "scene/animation.hpp"

namespace lancer {
namespace {

using Clock = std::chrono::steady_clock;

// A frame counts as rendered when its file decodes completely (every scanline, up to the PNG's
// last chunk) at the requested size. lancer's own writes are atomic, but a frame copied from
// another machine may have been cut short, and its header alone would still give the size; a
// file of another size (the scene or --width changed) is rendered again too.
bool frame_done(const std::string& path, const RenderSettings& r) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return false;
    try {
        Rgb8Image image = read_png(path);
        return image.width == r.width && image.height == r.height;
    } catch (const UserError&) {
        return false;
    }
}

// "orbit.png" -> "orbit_%03d.png", for the message that asks for a pattern.
std::string suggest_pattern(const std::string& output, int frames) {
    namespace fs = std::filesystem;
    fs::path p(output);
    std::string ext = p.extension().string().empty() ? ".png" : p.extension().string();
    fs::path name = p.stem().string() + "_" + frame_field(frames) + ext;
    return (p.parent_path() / name).string();
}

void create_frame_directory(const std::string& dir) {
    if (dir.empty()) return;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw UserError(fmt::format("cannot create the frame directory '{}': {}", dir, ec.message()));
}

}  // namespace

void add_animation_options(CLI::App& cmd, AnimationOptions& o) {
    cmd.add_option("--frames", o.frames, "Animated scenes: render frames A-B (or frame N) only, 0-based")
        ->check(not_empty("expected A-B or N, frame numbers from 0"));
    cmd.add_flag("--force", o.force, "Animated scenes: render frames again even when their files exist");
    cmd.add_option("--video", o.video, "Animated scenes: also encode the frames into FILE (.mp4, .webm or .gif) with ffmpeg")
        ->check(not_empty("expected FILE.mp4, .webm or .gif"));
}

int run_animation(const RenderOptions& options, const AnimationOptions& opts, const Scene& scene, RendererStart& renderer_start) {
    if (!scene.animation)
        throw UserError(fmt::format("{} has no [animation] table, so --frames and --video do not apply", options.scene));
    const Animation& animation = *scene.animation;
    const RenderSettings& r = scene.render;
    FrameRange range = opts.frames.empty() ? FrameRange{0, animation.frames - 1}
                                           : parse_frame_range(opts.frames, animation.frames);

    std::string pattern_text = options.output.empty() ? default_frame_pattern(options.scene, animation.frames) : options.output;
    std::optional<FramePattern> pattern = FramePattern::parse(pattern_text);
    if (!pattern) {
        // A plain name: one still of one frame, e.g. a poster image.
        if (range.single() && !opts.frames.empty() && opts.video.empty())
            return render_still(options, scene_for_frame(options, scene, range.first), options.output, renderer_start);
        throw UserError(fmt::format("-o {}: an animation needs a frame number in the name, such as {} "
                                    "(or --frames N for a single frame)",
                                    options.output, suggest_pattern(options.output, animation.frames)));
    }
    if (image_format_of(pattern->path(0)) != ImageFormat::Png)
        throw UserError(fmt::format("-o {}: animation frames are PNG images (a still may be .exr or .pfm)", pattern_text));
    if (!opts.video.empty()) {
        check_video_possible(opts.video);
        check_output_writable(opts.video);
    }

    std::vector<int> todo, skipped, unfinished;
    for (int k = range.first; k <= range.last; ++k) {
        if (opts.force) {
            todo.push_back(k);
        } else if (frame_done(pattern->path(k), r)) {
            skipped.push_back(k);
        } else {
            todo.push_back(k);
            std::error_code ec;
            if (std::filesystem::exists(pattern->path(k), ec)) unfinished.push_back(k);
        }
    }

    FrameProgress progress(options.quiet, static_cast<int>(todo.size()));
    if (!skipped.empty())
        progress.message(fmt::format("{}: skipping {} finished frame(s): {} (--force renders them again)", pattern->text(),
                                     skipped.size(), format_frame_list(skipped)));
    if (!unfinished.empty())
        progress.message(fmt::format("{}: rendering frame(s) {} again: their files do not decode completely at {}x{}",
                                     pattern->text(), format_frame_list(unfinished), r.width, r.height));

    for (int k : todo) check_output_is_not_an_input(pattern->path(k), scene_inputs(scene));
    if (!opts.video.empty()) check_output_is_not_an_input(opts.video, scene_inputs(scene));
    if (!todo.empty()) {
        create_frame_directory(pattern->directory());
        check_output_writable(pattern->path(todo.front()));

        Interrupts interrupts;
        auto start = Clock::now();
        std::unique_ptr<Renderer> renderer = renderer_start.take();
        try {
            renderer->prepare(scene_for_frame(options, scene, todo.front()),
                              [&](double) { return !interrupts.requested(); });
        } catch (const RenderCancelled&) {
            progress.clear();
            renderer.reset();
            throw Interrupted(interrupts.signal_number(),
                              fmt::format("frame {} ('{}') was not written; no frame was finished; run the same "
                                          "command again to resume",
                                          todo.front(), pattern->path(todo.front())));
        }
        double startup = seconds_since(start);
        std::vector<double> times;
        std::vector<int> written;
        double rays = 0.0;
        long long pixels = 0, refined = -1, camera_rays = 0;  // refined: -1 unless adaptive (camera_rays_summary)
        // Frames are written whole (write_png is atomic) or not at all: an interrupt stops the
        // frame in progress, and the frames before it stay as they are, to be resumed.
        auto stop = [&](int k, const std::string& path) {
            progress.clear();
            renderer.reset();
            throw Interrupted(interrupts.signal_number(),
                              fmt::format("frame {} ('{}') was not written; {} run the same command again to resume",
                                          k, path,
                                          written.empty() ? std::string("no frame was finished;")
                                                          : fmt::format("frame(s) {} are complete;", format_frame_list(written))));
        };
        for (int k : todo) {
            std::string path = pattern->path(k);
            if (interrupts.requested()) stop(k, path);
            Scene frame = scene_for_frame(options, scene, k);
            progress.begin(k, path);
            auto frame_start = Clock::now();
            FloatImage image;
            try {
                image = renderer->render(frame, [&](double f) {
                    progress.update(f);
                    return !interrupts.requested();
                });
            } catch (const RenderCancelled&) {
                stop(k, path);
            }
            write_png(path, to_srgb8(image, frame.render.tone));
            written.push_back(k);
            times.push_back(seconds_since(frame_start));
            rays += image.total_rays();
            pixels += static_cast<long long>(image.pixels.size());
            if (image.refined_pixels >= 0) {
                refined = std::max(0LL, refined) + image.refined_pixels;
                camera_rays += image.camera_rays;
            }
            progress.end(times.back());
        }
        double total = std::accumulate(times.begin(), times.end(), 0.0);
        double later = times.size() > 1 ? (total - times.front()) / double(times.size() - 1) : times.front();
        progress.message(fmt::format(
            "{}: rendered {} frame(s): {}, {}x{}, {}, {}: start-up {:.3f} s, first frame {:.3f} s, "
            "then {:.3f} s/frame, {:.2f} Mrays/s, peak RSS {} MiB",
            pattern->text(), todo.size(), format_frame_list(todo), r.width, r.height,
            camera_rays_summary(r.samples, pixels, refined, camera_rays),
            renderer->description(), startup, times.front(), later, rays / total / 1e6, peak_rss_mib()));
        renderer.reset();  // tear Vulkan down before counting validation messages
        if (int code = gpu::exit_code_after_validation(0)) return code;
    } else {
        progress.message(fmt::format("{}: nothing to render", pattern->text()));
    }

    if (!opts.video.empty()) {
        std::vector<int> missing;
        for (int k = 0; k < animation.frames; ++k)
            if (!frame_done(pattern->path(k), r)) missing.push_back(k);
        if (!missing.empty())
            throw UserError(fmt::format("cannot make {}: frame(s) {} of {} are missing (render them, e.g. --frames {})",
                                        opts.video, format_frame_list(missing), pattern->text(),
                                        missing.size() == 1 ? fmt::format("{}", missing[0])
                                                            : fmt::format("{}-{}", missing.front(), missing.back())));
        progress.status(fmt::format("{}: encoding {} frames with ffmpeg", opts.video, animation.frames));
        try {
            make_video(pattern->text(), animation.frames, animation.fps, opts.video);
        } catch (...) {
            progress.clear();
            throw;
        }
        progress.message(fmt::format("{}: {} frames at {:g} fps ({:.2f} s){}", opts.video, animation.frames,
                                     animation.fps, animation.frames / animation.fps,
                                     animation.cyclic ? ", loops seamlessly" : ""));
    }
    return 0;
}

}  // namespace lancer

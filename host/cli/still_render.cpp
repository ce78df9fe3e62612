#include "cli/still_render.hpp"

#include <chrono>
#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "app/interrupt.hpp"
#include "app/option_checks.hpp"
#include "cli/progress.hpp"
#include "gpu/vulkan/context.hpp"
#include "render/adaptive_render.hpp"

namespace lancer {

int render_still(const RenderOptions& options, Scene scene, const std::string& output, RendererStart& renderer_start) {
    check_output_writable(output);
    check_output_is_not_an_input(output, scene_inputs(scene));
    std::unique_ptr<Renderer> renderer = renderer_start.take();
    renderer->expect_one_still();

    Interrupts interrupts;
    ProgressLine progress(options.quiet);
    auto start = std::chrono::steady_clock::now();
    FloatImage image;
    try {
        PhaseLine preparing(options.quiet, "preparing " + output + " (the scene's buffers and trees, the shaders)");
        image = renderer->render_once(scene, [&](double f) {
            preparing.clear();  // the render's own progress from here
            progress.update(output, f);
            return !interrupts.requested();
        });
    } catch (const RenderCancelled&) {
        progress.clear();
        throw Interrupted(interrupts.signal_number(), "'" + output + "' was not written");
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ExrInfo info = image_info(scene);
    if (info.passes > 0) {  // a part of a farm render: stamped, so that lancer combine mixes no others
        info.scene_hash = scene_files_hash(scene);
        info.settings = render_settings_text(scene, options);
    }
    write_image(output, image, info);

    const RenderSettings& r = scene.render;
    double rays = image.total_rays();
    std::string per_pixel =
        scene.photons ? fmt::format("{} passes of {} photons and 1 camera ray/pixel", info.passes, scene.photons->count)
                      : camera_rays_summary(r.samples, static_cast<long long>(image.pixels.size()), image.refined_pixels,
                                            image.camera_rays);
    progress.finish(fmt::format("{}: {}x{}, {}, {}: {:.3f} s, {:.2f} Mrays/s ({:.1f} M rays), peak RSS {} MiB", output,
                                r.width, r.height, per_pixel, renderer->description(), seconds, rays / seconds / 1e6,
                                rays / 1e6, peak_rss_mib()));
    if (!options.quiet)
        for (const std::string& note : renderer->notes()) std::fprintf(stderr, "note: %s\n", note.c_str());
    renderer.reset();  // tear Vulkan down before counting validation messages
    return gpu::exit_code_after_validation(0);
}

}  // namespace lancer

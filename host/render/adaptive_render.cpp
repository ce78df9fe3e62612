#include "render/adaptive_render.hpp"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "image/adaptive.hpp"

namespace lancer {

FloatImage render_adaptive(const Scene& scene, AdaptivePicture& picture, const ProgressFn& progress,
                           const AdaptiveStepFn& step) {
    const RenderSettings& rs = scene.render;
    const double threshold = *rs.aa_threshold;
    const std::vector<int> grids = aa_grid_levels(rs.samples, rs.aa_depth);
    // Progress: the first rays a tenth, each refinement an equal share of the rest.
    const double first_share = 0.1;
    const double level_share = (1.0 - first_share) / double(std::max<std::size_t>(1, grids.size() - 1));
    auto part = [&](double from, double share) {
        return [&progress, from, share](double f) { return !progress || progress(from + f * share); };
    };

    Scene pass = scene;
    pass.render.samples = 1;
    picture.render_first(pass, part(0.0, first_share));
    long long refined_pixels = 0;
    long long camera_rays = static_cast<long long>(rs.width) * rs.height;
    auto current = [&] {
        FloatImage image = picture.picture();
        image.refined_pixels = refined_pixels;
        image.camera_rays = camera_rays;
        return image;
    };

    const int steps = int(grids.size()) - 1;
    int done = 0;
    for (std::size_t k = 1; k < grids.size(); ++k) {
        const std::size_t chosen = picture.choose(threshold, k > 1 && rs.aa_method == AaMethod::Spread);
        if (chosen == 0) break;
        if (step) step(current(), done, steps, false);
        pass.render.samples = grids[k];
        const bool keep_spread = rs.aa_method == AaMethod::Spread && k + 1 < grids.size();
        picture.refine(pass, keep_spread, part(first_share + double(k - 1) * level_share, level_share));
        if (k == 1) refined_pixels = static_cast<long long>(chosen);
        camera_rays += static_cast<long long>(chosen) * grids[k] * grids[k];
        done = int(k);
    }
    FloatImage image = current();
    if (step) step(image, done, steps, true);
    return image;
}

std::string camera_rays_summary(int samples, long long pixels, long long refined, long long camera_rays) {
    const int grid = samples * samples;
    if (refined < 0) return fmt::format("{} rays/pixel", grid);
    const double share = pixels > 0 ? double(refined) / double(pixels) : 0.0;
    const double per_pixel = pixels > 0 ? double(camera_rays) / double(pixels) : 0.0;
    return fmt::format("{:.2f} rays/pixel on average ({:.1f}% of pixels refined, up to {})", per_pixel, 100.0 * share, grid);
}

}  // namespace lancer

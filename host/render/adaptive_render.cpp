#include "render/adaptive_render.hpp"

#include <fmt/format.h>

#include "image/adaptive.hpp"

namespace lancer {

FloatImage render_adaptive(const Scene& scene, const RenderEveryPixel& every_pixel, const RenderListedPixels& listed,
                           const ProgressFn& progress, const AdaptiveStepFn& step) {
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
    FloatImage image = every_pixel(pass, part(0.0, first_share));
    image.refined_pixels = 0;
    image.camera_rays = static_cast<long long>(image.pixels.size());

    std::vector<std::uint32_t> pixels;  // those the last pass traced (after the first: all)
    std::vector<ListedPixel> last;
    const int steps = int(grids.size()) - 1;
    int done = 0;
    for (std::size_t k = 1; k < grids.size(); ++k) {
        std::vector<char> candidates;
        if (k > 1) {
            candidates.assign(image.pixels.size(), 0);
            for (std::uint32_t p : pixels) candidates[p] = 1;
        }
        std::vector<std::uint32_t> next = pixels_to_refine(image, threshold, candidates);
        if (k > 1 && rs.aa_method == AaMethod::Spread) {
            std::vector<char> refine(image.pixels.size(), 0);
            for (std::uint32_t p : next) refine[p] = 1;
            for (std::size_t i = 0; i < pixels.size(); ++i)
                if (sample_spread(last[i].lo, last[i].hi) > threshold) refine[pixels[i]] = 1;
            next.clear();
            for (std::uint32_t p : pixels)
                if (refine[p]) next.push_back(p);
        }
        if (next.empty()) break;
        if (step) step(image, done, steps, false);
        pass.render.samples = grids[k];
        const bool spread = rs.aa_method == AaMethod::Spread && k + 1 < grids.size();
        last = listed(pass, next, spread, part(first_share + double(k - 1) * level_share, level_share));
        // A refined pixel's colour is its last grid's; its ray count says all it traced.
        for (std::size_t i = 0; i < next.size(); ++i) {
            glm::vec4& p = image.pixels[next[i]];
            p = glm::vec4(glm::vec3(last[i].colour), p.a + last[i].colour.a);
        }
        if (k == 1) image.refined_pixels = static_cast<long long>(next.size());
        image.camera_rays += static_cast<long long>(next.size()) * grids[k] * grids[k];
        pixels = std::move(next);
        done = int(k);
    }
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

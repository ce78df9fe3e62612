#pragma once
// Adaptive anti-aliasing, the order of its passes, for both renderers: every pixel's first ray
// (a one-sample render), then grid after grid (image/adaptive.hpp's aa_grid_levels) for the
// pixels that the last pass left in doubt. A refined pixel's colour is its last grid's alone,
// traced exactly as a full render traces that pixel, so at threshold 0 (every pixel refined to
// the end) the picture is the full render's byte for byte.
//
// Which pixels go on: after the first ray, those that differ from a neighbour by more than the
// threshold (POV-Ray's +AM1 test); after a grid, among the pixels that grid refined, the same
// test and, with AaMethod::Spread, also those whose own samples spread by more than the
// threshold (image/adaptive.hpp's sample_spread; POV-Ray's +AM2 asks this of a pixel's corners).
// The spread alone would stop a pixel whose coarse grid happens to miss an edge its finer grid
// crosses (a checker line between the rows of a 2 x 2 grid); its neighbours see that edge.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/renderer.hpp"

namespace lancer {

// One pixel of a listed render: the mean of its grid's samples (a = rays traced) and, when the
// render was asked for them, the per-channel extremes of its samples' linear colours.
struct ListedPixel {
    glm::vec4 colour{0.0f};
    glm::vec3 lo{0.0f}, hi{0.0f};
};

// What a renderer provides: a render of every pixel (the scene's samples is 1), and a render of
// the listed pixels (y * width + x) with the scene's samples as their grid, with the spread of
// the samples when `spread` is set.
using RenderEveryPixel = std::function<FloatImage(const Scene&, const ProgressFn&)>;
using RenderListedPixels = std::function<std::vector<ListedPixel>(const Scene&, const std::vector<std::uint32_t>&,
                                                                  bool spread, const ProgressFn&)>;

// Called with the picture after each step (0: every pixel's first ray) of at most `steps` more,
// and whether it is the final one (progressive display: the viewer).
using AdaptiveStepFn = std::function<void(const FloatImage& image, int step, int steps, bool final)>;

// The adaptive render of `scene` (scene.render.aa_threshold is set); the image's refined_pixels
// and camera_rays say what it traced.
FloatImage render_adaptive(const Scene& scene, const RenderEveryPixel& every_pixel, const RenderListedPixels& listed,
                           const ProgressFn& progress, const AdaptiveStepFn& step = {});

// The summary line's camera rays: "9 rays/pixel", or for adaptive anti-aliasing (refined >= 0:
// how many of the `pixels` were refined at least once, camera_rays: how many rays they all got)
// "1.84 rays/pixel on average (10.5% of pixels refined, up to 9)".
std::string camera_rays_summary(int samples, long long pixels, long long refined, long long camera_rays);

}  // namespace lancer

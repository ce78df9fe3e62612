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
#include <cstddef>
#include <functional>
#include <string>

#include "render/renderer.hpp"

namespace lancer {

// What a renderer provides: a picture it keeps between the passes, the choice of the pixels that
// go on from it, and their refinement. HostAdaptivePicture (render/host_adaptive_picture.hpp)
// keeps it on the host; the GPU keeps it on the device (gpu/passes/refine_selection.hpp).
class AdaptivePicture {
public:
    virtual ~AdaptivePicture() = default;
    // Renders every pixel's first ray (the scene's samples is 1): the picture to refine.
    virtual void render_first(const Scene& one_ray, const ProgressFn& progress) = 0;
    // Chooses the pixels of the next refinement by image/adaptive.hpp's rule (pixels_to_refine)
    // among the candidates: every pixel before the first refinement, afterwards the pixels the
    // last one traced; with `by_spread`, also those of the last refinement's pixels whose samples
    // spread by more than the threshold. Returns how many.
    virtual std::size_t choose(double threshold, bool by_spread) = 0;
    // Traces the chosen pixels with the scene's samples as their grid, and with `keep_spread`
    // keeps their samples' spread for the next choice. A refined pixel's colour becomes its grid's
    // mean; its rays add up.
    virtual void refine(const Scene& grid, bool keep_spread, const ProgressFn& progress) = 0;
    // The picture as it is now.
    virtual FloatImage picture() = 0;
};

// Called with the picture after each step (0: every pixel's first ray) of at most `steps` more,
// and whether it is the final one (progressive display: the viewer).
using AdaptiveStepFn = std::function<void(const FloatImage& image, int step, int steps, bool final)>;

// The adaptive render of `scene` (scene.render.aa_threshold is set) through `picture`; the
// image's refined_pixels and camera_rays say what it traced.
FloatImage render_adaptive(const Scene& scene, AdaptivePicture& picture, const ProgressFn& progress,
                           const AdaptiveStepFn& step = {});

// The summary line's camera rays: "9 rays/pixel", or for adaptive anti-aliasing (refined >= 0:
// how many of the `pixels` were refined at least once, camera_rays: how many rays they all got)
// "1.84 rays/pixel on average (10.5% of pixels refined, up to 9)".
std::string camera_rays_summary(int samples, long long pixels, long long refined, long long camera_rays);

}  // namespace lancer

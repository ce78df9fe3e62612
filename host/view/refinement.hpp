#pragma once
// What the viewer renders for one camera: a quick preview while the camera moves, then passes
// over the N x N sample grid until the picture is the one `lancer render` makes. Pure planning
// and pixel arithmetic; the render worker runs it.
#include <cstdint>
#include <vector>

#include "image/image.hpp"
#include "scene/scene.hpp"

namespace lancer::view {

struct SamplePass {
    std::uint32_t first = 0;  // index into the grid, row by row
    std::uint32_t count = 0;
    bool operator==(const SamplePass&) const = default;
};

// The passes that refine an N x N grid, in order and covering it exactly: 1 sample, then as many
// as were done so far (the sample count doubles, so every pass halves the noise-like error of
// the one before and costs about as much as all the passes before it), with a short tail merged
// into the last pass. 3 x 3: [0,1) [1,2) [2,4) [4,9).
std::vector<SamplePass> refinement_passes(int samples_per_side);

// What a still of `scene` is made of: its N x N grid samples, or with photon mapping its photon
// passes (each one camera sample per pixel and a photon map: the caustics refine with the
// anti-aliasing); and the passes that refine them, as refinement_passes does for a grid.
std::uint32_t refinement_total(const Scene& scene);
std::vector<SamplePass> refinement_plan(const Scene& scene);

// The preview of `scene` while the camera moves: 1 sample per pixel (the pixel's centre) at
// 1/`divisor` of the width and height (at least 1 x 1), same camera and aspect ratio; with
// photon mapping, one pass of an eighth of the photons (at least 1000).
Scene preview_scene(const Scene& scene, int divisor);

// The first divisor to try, from the time of one sample per pixel at full size: the smallest
// power of two whose preview (1/d^2 of the pixels) fits `budget_ms`.
int preview_divisor_for(double full_size_ms, double budget_ms, int max_divisor);

// Keeps previews near a time budget as the camera moves: a slower preview than `budget_ms`
// doubles the divisor next time (halves each side); one much faster halves it, down to 1.
int next_preview_divisor(int divisor, double preview_ms, double budget_ms, int max_divisor);

// The image after `samples_done` of a pass sequence: sums / samples_done (pass sums are not
// divided until the last pass, which divides itself; then samples_done is the whole grid and
// `final_pass` is true). Each is converted as `lancer render` writes a picture, through the
// scene's tone mapping; the final one gives exactly its bytes.
Rgb8Image display_image(const FloatImage& sums, std::uint32_t samples_done, bool final_pass,
                        const ToneMapping& tone = {});

}  // namespace lancer::view

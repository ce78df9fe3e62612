#pragma once
// Adaptive anti-aliasing's picture kept on the host (render/adaptive_render.hpp): the pixels that
// go on are chosen by pixels_to_refine and the spread rule, and traced by the renderer's render
// of listed pixels. The CPU reference's way; the GPU's where the device cannot hold the picture.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/adaptive_render.hpp"

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

class HostAdaptivePicture final : public AdaptivePicture {
public:
    HostAdaptivePicture(RenderEveryPixel every_pixel, RenderListedPixels listed)
        : every_pixel_(std::move(every_pixel)), listed_(std::move(listed)) {}

    void render_first(const Scene& one_ray, const ProgressFn& progress) override;
    std::size_t choose(double threshold, bool by_spread) override;
    void refine(const Scene& grid, bool keep_spread, const ProgressFn& progress) override;
    FloatImage picture() override { return image_; }

private:
    RenderEveryPixel every_pixel_;
    RenderListedPixels listed_;
    FloatImage image_;
    bool refined_ = false;               // a refinement has run: the candidates are its pixels
    std::vector<std::uint32_t> traced_;  // the last refinement's pixels
    std::vector<ListedPixel> last_;      // and what it traced, in that order
    std::vector<std::uint32_t> chosen_;  // the next refinement's
};

}  // namespace lancer

#pragma once
// A picture the render worker hands to the window, with what the title bar and the terminal say
// about it.
#include <cstdint>
#include <string>

#include "image/image.hpp"
#include "scene/scene.hpp"

namespace lancer::view {

struct ShownFrame {
    enum class Kind { Preview, Pass, Final, Recording };
    Kind kind = Kind::Preview;
    Rgb8Image image;
    std::uint64_t generation = 0;  // of the view it belongs to (RenderWorker::show); 0 for recordings
    CameraSpec camera;
    int width = 0, height = 0, samples = 1;  // the scene's full image size and N of the N x N grid
    std::uint32_t samples_done = 0;          // Pass, Final: of the N x N grid
    // Pass, Final of adaptive anti-aliasing: the pixels refined so far, and the camera rays
    // traced in all (FloatImage's counts); -1 when the grid is refined in sample passes.
    long long refined_pixels = -1, camera_rays = -1;
    int pass = 0, passes = 0;                // Pass, Final: 1-based index and count
    int preview_divisor = 1;                 // Preview: 1/divisor of each side, 1 sample per pixel
    double render_ms = 0.0;  // of this picture: the preview, the pass, the recorded frame
    double rays = 0.0;       // traced for it
    double convert_ms = 0.0; // turning it into 8-bit sRGB for the window
    double view_ms = 0.0;    // Pass, Final: since the refinement of this view started
    double view_rays = 0.0;  // Pass, Final: traced since then
    std::string status;      // Recording: "recording orbit: frame 3/120"
};

}  // namespace lancer::view

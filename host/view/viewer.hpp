#pragma once
// `lancer view`: the interactive window. The event loop (this) owns the window, the camera and
// the scene; the render worker owns the GPU; a watcher thread reports edited shader and scene
// files. They talk through SDL events, so the loop sleeps until something happens.
#include <optional>
#include <string>

#include "app/render_options.hpp"

namespace lancer::view {

struct ViewerOptions {
    RenderOptions render;       // the scene, size and sample overrides, the device; -o for `p`
    std::optional<int> frame;   // of an animated scene
    std::string dump_frame;     // --dump-frame: the window's pixels after each finished refinement
    int record_frames = 120;    // frames of the sequences f and l record
};

// Returns the exit code: 0, or 1 when the validation layer reported anything.
int run_viewer(const ViewerOptions& options);

}  // namespace lancer::view

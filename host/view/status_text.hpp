#pragma once
// What the viewer says about a picture: the window title (camera position, frame time, rays/s)
// and the terminal line of a finished refinement.
#include <string>

#include "view/shown_frame.hpp"

namespace lancer::view {

// "lancer view | seed.toml | eye (0.00, 3.20, -9.00) | 9/9 samples in 312 ms | 17.5 Mrays/s"
std::string window_title(const std::string& scene_name, const ShownFrame& frame);

// "view: refined 640x360, 9 rays/pixel in 0.312 s (4 passes, 17.5 Mrays/s); camera: eye = [...], ..."
std::string refined_line(const ShownFrame& frame);

}  // namespace lancer::view

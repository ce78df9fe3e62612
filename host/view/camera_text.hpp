#pragma once
// A camera as the TOML a scene file takes, with every double printed so that it reads back
// to the same bits: what the viewer prints when it saves a picture, for `lancer render`.
#include <string>

#include "scene/scene.hpp"

namespace lancer::view {

// "eye = [0, 3.2, -9], look_at = [0, 0.9, 0], up = [0, 1, 0], fov = 45"
std::string camera_toml(const CameraSpec& camera);

}  // namespace lancer::view

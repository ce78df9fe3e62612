#include "view/camera_text.hpp"

#include <fmt/format.h>

namespace lancer::view {
namespace {

// fmt prints the shortest decimal that reads back to the same double.
std::string vec(const dvec3& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

}  // namespace

std::string camera_toml(const CameraSpec& c) {
    return fmt::format("eye = {}, look_at = {}, up = {}, fov = {}", vec(c.eye), vec(c.look_at), vec(c.up), c.fov_deg);
}

}  // namespace lancer::view

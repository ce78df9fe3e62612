#pragma once
// Bounding boxes of scene shapes. Unbounded shapes (planes) have none.
#include <optional>

#include "accel/aabb.hpp"
#include "scene/scene.hpp"

namespace lancer {

std::optional<Aabb> shape_bounds(const Shape& shape);

}  // namespace lancer

#pragma once
// Bounding boxes of scene shapes and objects. Unbounded shapes (planes) have none.
#include <optional>

#include "accel/aabb.hpp"
#include "scene/scene.hpp"

namespace lancer {

std::optional<Aabb> shape_bounds(const Shape& shape);
// The world box of an object: its shape's, carried through its placement where the shape keeps
// its own coordinates.
std::optional<Aabb> object_bounds(const Object& o);

}  // namespace lancer

#pragma once
// Bounding boxes of scene shapes and objects. Unbounded shapes (planes) have none.
#include <cstdint>
#include <optional>
#include <vector>

#include "scene/aabb.hpp"
#include "scene/scene.hpp"

namespace lancer {

std::optional<Aabb> shape_bounds(const Shape& shape);

// Sets what a blob keeps beside its components: its box (its components of positive strength,
// where the field can reach its threshold) and the tree over their boxes.
void prepare_blob(Blob& o);
// The world box of an object: its shape's, carried through its placement where the shape keeps
// its own coordinates.
std::optional<Aabb> object_bounds(const Object& o);
// The box of a CSG combination of `leaves` by `program` (shapes.h's CSG_* ops): the overlap of an
// intersection's, the hull of a union's, a difference's first's; nothing where it is unbounded
// (a half-space alone, an inverse); an empty box where an intersection's boxes do not meet.
std::optional<Aabb> csg_bounds(const std::vector<Object>& leaves, const std::vector<std::uint32_t>& program);

}  // namespace lancer

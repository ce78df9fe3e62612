#pragma once
// Boxes around the families of analytic shapes that the shader tests outside the BVH, each
// family in a loop of its own (shaders/scene.glsl). lavapipe runs every `if`'s body for every
// SIMD lane, whatever the condition; it saves work only where a loop runs fewer times. So a
// ray that misses a family's box gives that family's loop no trips, and where the family is
// cut in two, a ray that misses one half's box skips that half (docs/performance.md).
#include <array>
#include <optional>
#include <span>
#include <utility>

#include "scene/aabb.hpp"
#include "gpu/layout.hpp"

namespace lancer::gpu {

struct FamilyBoxes {
    bool boxed = false;  // a ray that misses halves[0] (with `split`: either half) skips it
    bool split = false;
    std::array<Aabb, 2> halves{};  // [0]: the first split_at members (all without `split`), [1]: the rest
    uint split_at = 0;             // within the family
};

using PrimitiveWithBox = std::pair<Primitive, std::optional<Aabb>>;

// The boxes for one family's members outside the BVH, in the order they will be packed; a
// split sorts them along its box's longest axis (which the pictures do not depend on: ties go
// by a stable key). `scene_box` is the box around every bounded primitive. A box pays where it
// stands for several tests and rays often miss it: around one shape it is one more test, and
// around walls that enclose everything (the Cornell box) rays never miss it.
FamilyBoxes box_family(std::span<PrimitiveWithBox> members, const Aabb& scene_box);

}  // namespace lancer::gpu

#pragma once
// Doubles to the floats the shader reads: vectors, and bounds rounded outward so that a float
// box still holds what its double box held.
#include "scene/aabb.hpp"
#include "core/float_rounding.hpp"
#include "gpu/layout.hpp"

namespace lancer::gpu {

inline vec4 v4(const glm::dvec3& v, double w = 0.0) { return vec4(float(v.x), float(v.y), float(v.z), float(w)); }

// A box for the shader's slab test, rounded outward to float and padded by a few float ulps of
// its coordinates: the slab test has rounding errors of its own, and a ray aimed exactly at a
// box's edge (a patch corner, which is a control point and so on the box) must not slip past it.
void pack_box(const Aabb& box, vec4& lo, vec4& hi);

}  // namespace lancer::gpu

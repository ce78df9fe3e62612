#pragma once
// The CPU reference's ray, hit and offset rule (double precision throughout).
#include <algorithm>
#include <cmath>

#include "scene/scene.hpp"

namespace lancer::cpu {

struct Ray {
    dvec3 origin;
    dvec3 dir;  // unit length
};

// Secondary rays start this far off the surface; scaled by |p| so that rounding of the hit point
// never puts the new origin behind the surface. The GPU uses the same rule (shaders/common.glsl).
inline double ray_offset(const dvec3& p) {
    return 1e-4 * std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

}  // namespace lancer::cpu

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

// Secondary rays start this far off the surface; scaled by the hit's distance from `origin` (the
// scene's working origin, scene/camera.hpp) so that rounding of the hit point never puts the new
// origin behind the surface. The GPU uses the same rule in its coordinates, which start at that
// origin (shaders/common.glsl): a scene moved far away, camera with it, keeps its offsets.
inline double ray_offset(const dvec3& p, const dvec3& origin) {
    const dvec3 d = p - origin;
    return 1e-4 * std::max({1.0, std::abs(d.x), std::abs(d.y), std::abs(d.z)});
}

// The largest channel of a colour or weight.
inline double max_of(const dvec3& v) { return std::max({v.r, v.g, v.b}); }

}  // namespace lancer::cpu

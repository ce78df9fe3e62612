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
// scene's working origin, scene/camera.hpp), so that a scene moved far away, camera with it, keeps
// its offsets. 1e-7 of that is far above the error of every hit the reference computes (its
// certified roots are accurate to about 1e-10 of the surface's size, its analytic ones to
// double's rounding), and below the GPU's offsets (its hits' float error bounds,
// shaders/common.glsl): the two backends then shadow the same points, edges included, and thin
// sheets (Dini's surface far from the origin) are not stepped over.
inline double ray_offset(const dvec3& p, const dvec3& origin) {
    const dvec3 d = p - origin;
    return 1e-7 * std::max({1.0, std::abs(d.x), std::abs(d.y), std::abs(d.z)});
}

// The largest channel of a colour or weight.
inline double max_of(const dvec3& v) { return std::max({v.r, v.g, v.b}); }

}  // namespace lancer::cpu

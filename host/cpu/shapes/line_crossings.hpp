#pragma once
// The crossings of a surface that closes a solid (shapes.hpp's LineCrossing) found by a nearest-
// hit search run again from a hair past each root: the parametric surfaces' certified search and
// a mesh's tree walk share it (Bezier patches give all their roots at once).
#include <cstddef>
#include <vector>

#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {

// Whether a crossing with unit normal n (S_u x S_v, or a triangle's winding) leaves the solid,
// the normals pointing out where outward is +1 and in where it is -1.
inline bool leaves_solid(int outward, const dvec3& n, const Ray& ray) { return outward * glm::dot(n, ray.dir) > 0.0; }

// nearest(t_min, t_max): the nearest SurfaceHit in (t_min, t_max), or none. `gap`, in units of t,
// must exceed the search's error, so that a root is not found twice; at most 256 crossings.
template <class Nearest>
std::vector<LineCrossing> crossings_by_search(Nearest&& nearest, int outward, const Ray& ray, double t0, double t1, double gap) {
    constexpr std::size_t kMostCrossings = 256;
    std::vector<LineCrossing> crossings;
    for (double t = t0; crossings.size() < kMostCrossings;) {
        const auto h = nearest(t, t1);
        if (!h) break;
        crossings.push_back({h->t, leaves_solid(outward, h->normal, ray)});
        t = h->t + gap;
    }
    return crossings;
}

}  // namespace lancer::cpu

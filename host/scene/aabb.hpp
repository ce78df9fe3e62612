#pragma once
// Axis-aligned bounding boxes in double precision (the BVH is built in double, then rounded
// outward when converted to float for the GPU, so no ray can slip between float boxes).
#include <algorithm>
#include <limits>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace lancer {

struct Aabb {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void extend(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void extend(const Aabb& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    glm::dvec3 center() const { return 0.5 * (lo + hi); }
    glm::dvec3 extent() const { return hi - lo; }
    double surface_area() const {
        if (empty()) return 0.0;
        glm::dvec3 e = extent();
        return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
    friend bool operator==(const Aabb&, const Aabb&) = default;
    bool contains(const Aabb& b) const {
        return b.lo.x >= lo.x && b.lo.y >= lo.y && b.lo.z >= lo.z && b.hi.x <= hi.x && b.hi.y <= hi.y && b.hi.z <= hi.z;
    }
};

}  // namespace lancer

#pragma once
// Two planes whose intersection is a ray's line: the exact patch and parametric intersectors
// reduce "the ray meets the surface" to "the surface point lies in both planes".
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "scene/scene.hpp"

namespace lancer::cpu {

// Rotating the two planes off the coordinate axes keeps them from containing the planar
// iso-curves that axis-aligned data is full of (the teapot's z = 0.9 row): such a plane makes f
// vanish on a whole parameter line and turns that line's u into a multiple eigenvalue.
inline constexpr double kPlaneAngle = 0.7137;

// Unit normals of the two planes through a ray of unit direction d: perpendicular to d and to
// each other.
inline std::pair<dvec3, dvec3> ray_planes(const dvec3& d) {
    dvec3 a = glm::abs(d);
    dvec3 axis = (a.x <= a.y && a.x <= a.z) ? dvec3(1, 0, 0) : (a.y <= a.z ? dvec3(0, 1, 0) : dvec3(0, 0, 1));
    dvec3 e1 = glm::normalize(glm::cross(d, axis));
    dvec3 e2 = glm::cross(d, e1);
    dvec3 n1 = std::cos(kPlaneAngle) * e1 + std::sin(kPlaneAngle) * e2;
    return {n1, glm::cross(d, n1)};
}

}  // namespace lancer::cpu

#pragma once
// Whether every coordinate of a point is a finite number: a point of a surface where its
// equations are undefined (0 * log of a negative, a pole) is NaN or infinite.
#include <cmath>

#include <glm/vec3.hpp>

namespace lancer {

inline bool all_finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace lancer

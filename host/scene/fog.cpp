// POV-Ray's fog along a segment, exactly (scene.hpp, fog_depth). Twin of shaders/fog.glsl.
// Constant fog's depth is the length. Ground fog's density is 1 at heights Y <= 0 and
// 1 / (1 + Y^2) above (Y the height above the offset, in altitudes): along a segment whose
// height grows by k per unit length its integral is (G(Y_end) - G(Y_start)) / k with
// G(Y) = Y below 0 and atan(Y) above, written so that nearly level segments keep their precision
// (atan(b) - atan(a) = atan((b - a) / (1 + a b)) for a, b > 0).
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "scene/scene.hpp"

namespace lancer {

namespace {

// atan(x) / x, 1 at 0.
double atan_over(double x) { return std::abs(x) < 1e-8 ? 1.0 : std::atan(x) / x; }

}  // namespace

double fog_depth(const Fog& fog, const dvec3& from, const dvec3& dir, double length) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (!fog.ground) return length;
    const Fog::Ground& g = *fog.ground;
    const double a = (glm::dot(from, g.up) - g.offset) / g.altitude;  // Y where the segment starts
    const double k = glm::dot(dir, g.up) / g.altitude;                 // dY per unit of length
    if (std::isinf(length)) {
        if (!(k > 0.0)) return inf;  // level or down: into the fog for ever
        return (a > 0.0 ? std::atan(1.0 / a) : M_PI / 2.0 - a) / k;
    }
    const double b = a + k * length;
    if (a <= 0.0 && b <= 0.0) return length;
    if (a > 0.0 && b > 0.0) return length * atan_over(k * length / (1.0 + a * b)) / (1.0 + a * b);
    const double lo = std::min(a, b), hi = std::max(a, b);
    return length * (std::atan(hi) - lo) / (hi - lo);
}

}  // namespace lancer

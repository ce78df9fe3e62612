#include "surface/parametric_surface.hpp"

#include <cmath>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "surface/expr/evaluate.hpp"

namespace lancer::surface {
namespace {

// Pu x Pv counts as degenerate when it is tiny compared with the partials themselves: one of
// them (nearly) vanishes, as at a sphere's pole, or they are (nearly) parallel. The direction of
// such a cross product is mostly rounding noise.
constexpr double kDegenerate = 1e-10;

std::optional<dvec3> regular_normal(const SurfacePoint& p) {
    dvec3 n = glm::cross(p.Pu, p.Pv);
    double length = glm::length(n);
    double scale = glm::dot(p.Pu, p.Pu) + glm::dot(p.Pv, p.Pv);
    if (!std::isfinite(length) || !std::isfinite(scale) || !(length > kDegenerate * scale)) return std::nullopt;
    return n / length;
}

// Any unit vector perpendicular to a (or +z when a is zero), the last resort.
dvec3 some_perpendicular(const dvec3& a) {
    if (!(glm::length(a) > 0.0) || !std::isfinite(glm::length(a))) return {0.0, 0.0, 1.0};
    dvec3 axis = std::abs(a.x) < std::abs(a.y) ? (std::abs(a.x) < std::abs(a.z) ? dvec3(1, 0, 0) : dvec3(0, 0, 1))
                                               : (std::abs(a.y) < std::abs(a.z) ? dvec3(0, 1, 0) : dvec3(0, 0, 1));
    return glm::normalize(glm::cross(a, axis));
}

// +1 or -1: the direction from x towards the middle of [lo, hi].
double inward(double x, double lo, double hi) { return x <= 0.5 * (lo + hi) ? 1.0 : -1.0; }

}  // namespace

SurfacePoint evaluate_surface(const ParametricSurface& s, double u, double v) {
    auto du = Dual<double>::variable_u(u), dv = Dual<double>::variable_v(v);
    Dual<double> x = evaluate(s.x, du, dv), y = evaluate(s.y, du, dv), z = evaluate(s.z, du, dv);
    glm::dmat3 linear(s.to_world);
    return {dvec3(s.to_world * glm::dvec4(x.v, y.v, z.v, 1.0)), linear * dvec3(x.du, y.du, z.du),
            linear * dvec3(x.dv, y.dv, z.dv)};
}

dvec3 surface_normal(const ParametricSurface& s, double u, double v) {
    SurfacePoint p = evaluate_surface(s, u, v);
    if (auto n = regular_normal(p)) return *n;
    // Walk towards the inside of the domain in growing steps until the parametrisation is
    // regular: the first regular normal is the limit normal to within about the step.
    double su = inward(u, s.u0, s.u1) * std::max(s.u1 - s.u0, 1e-300);
    double sv = inward(v, s.v0, s.v1) * std::max(s.v1 - s.v0, 1e-300);
    for (double step = 1e-9; step < 0.2; step *= 8.0) {
        if (auto n = regular_normal(evaluate_surface(s, u + step * su, v + step * sv))) return *n;
    }
    return some_perpendicular(glm::length(p.Pu) >= glm::length(p.Pv) ? p.Pu : p.Pv);
}

}  // namespace lancer::surface

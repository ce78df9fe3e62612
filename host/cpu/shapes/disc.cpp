// Ray/disc (POV-Ray's disc): hit the plane through the centre, then keep the hit where its
// distance r from the centre has hole_radius <= r <= radius (both edges belong to the disc).
#include <cmath>

#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {

std::optional<SurfaceHit> intersect(const Disc& d, const Ray& ray, double t_min, double t_max) {
    double denom = glm::dot(d.normal, ray.dir);
    if (denom == 0.0) return std::nullopt;  // parallel, including a ray lying in the disc's plane
    dvec3 to_center = d.center - ray.origin;
    double t = glm::dot(to_center, d.normal) / denom;
    if (t <= t_min || t >= t_max) return std::nullopt;
    dvec3 w = t * ray.dir - to_center;  // from the centre to the hit
    double r2 = glm::dot(w, w);
    if (r2 > d.radius * d.radius || r2 < d.hole_radius * d.hole_radius) return std::nullopt;
    return SurfaceHit{t, d.normal};
}

// Polar: u the angle about the normal from u_axis toward v_axis, over 2 pi, in [0, 1); v from 0 at
// the hole's edge (the centre without a hole) to 1 at the rim.
glm::dvec2 texture_uv(const Disc& d, const dvec3& p) {
    dvec3 w = p - d.center;
    double x = glm::dot(w, d.u_axis), y = glm::dot(w, d.v_axis);
    double angle = (x == 0.0 && y == 0.0) ? 0.0 : std::atan2(y, x);
    if (angle < 0.0) angle += 2.0 * M_PI;
    double u = angle / (2.0 * M_PI);
    if (u >= 1.0) u = 0.0;
    double v = (std::sqrt(x * x + y * y) - d.hole_radius) / (d.radius - d.hole_radius);
    return {u, v};
}

}  // namespace lancer::cpu

// Ray/sphere: |o + t d - c|^2 = r^2 with |d| = 1.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {

std::optional<double> sphere_hit_t(const dvec3& center, double radius, const Ray& ray, double t_min, double t_max) {
    dvec3 f = ray.origin - center;
    double b = glm::dot(f, ray.dir);
    // r^2 - |f - b d|^2 is the discriminant without the cancellation of b^2 - (|f|^2 - r^2).
    dvec3 perp = f - b * ray.dir;
    double disc = radius * radius - glm::dot(perp, perp);
    if (disc < 0.0) return std::nullopt;
    double root = std::sqrt(disc);
    double c = glm::dot(f, f) - radius * radius;
    double q = b > 0.0 ? -b - root : -b + root;  // the larger-magnitude root, computed without cancellation
    double t0 = q != 0.0 ? c / q : 0.0;
    double t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_min && t0 < t_max) return t0;
    if (t1 > t_min && t1 < t_max) return t1;
    return std::nullopt;
}

std::optional<SurfaceHit> intersect(const Sphere& s, const Ray& ray, double t_min, double t_max) {
    const std::optional<double> t = sphere_hit_t(s.center, s.radius, ray, t_min, t_max);
    if (!t) return std::nullopt;
    return SurfaceHit{*t, (ray.origin + *t * ray.dir - s.center) / s.radius};
}

// Longitude and latitude in the sphere's own frame: u = 0.5 (the middle of the image) faces -z,
// u grows toward +x, v from 0 at the south pole (-y) to 1 at the north pole.
glm::dvec2 texture_uv(const Sphere& s, const dvec3& p) {
    dvec3 d = glm::transpose(s.orientation) * ((p - s.center) / s.radius);
    double longitude = (d.x == 0.0 && d.z == 0.0) ? 0.0 : std::atan2(d.x, -d.z);
    double latitude = std::asin(std::clamp(d.y, -1.0, 1.0));
    return {0.5 + longitude / (2.0 * M_PI), 0.5 + latitude / M_PI};
}

}  // namespace lancer::cpu

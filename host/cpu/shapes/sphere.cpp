// Ray/sphere: |o + t d - c|^2 = r^2 with |d| = 1.
#include <cmath>

#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {

std::optional<SurfaceHit> intersect(const Sphere& s, const Ray& ray, double t_min, double t_max) {
    dvec3 f = ray.origin - s.center;
    double b = glm::dot(f, ray.dir);
    // r^2 - |f - b d|^2 is the discriminant without the cancellation of b^2 - (|f|^2 - r^2).
    dvec3 perp = f - b * ray.dir;
    double disc = s.radius * s.radius - glm::dot(perp, perp);
    if (disc < 0.0) return std::nullopt;
    double root = std::sqrt(disc);
    double c = glm::dot(f, f) - s.radius * s.radius;
    double q = b > 0.0 ? -b - root : -b + root;  // the larger-magnitude root, computed without cancellation
    double t0 = q != 0.0 ? c / q : 0.0;
    double t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    double t;
    if (t0 > t_min && t0 < t_max) {
        t = t0;
    } else if (t1 > t_min && t1 < t_max) {
        t = t1;
    } else {
        return std::nullopt;
    }
    return SurfaceHit{t, (ray.origin + t * ray.dir - s.center) / s.radius};
}

}  // namespace lancer::cpu

// Ray/parallelogram: hit the supporting plane, then solve p - corner = a edge_u + b edge_v.
#include <cmath>

#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {

std::optional<SurfaceHit> intersect(const Rectangle& r, const Ray& ray, double t_min, double t_max) {
    dvec3 n = glm::cross(r.edge_u, r.edge_v);
    double denom = glm::dot(n, ray.dir);
    if (denom == 0.0) return std::nullopt;
    double t = glm::dot(r.corner - ray.origin, n) / denom;
    if (t <= t_min || t >= t_max) return std::nullopt;
    dvec3 q = ray.origin + t * ray.dir - r.corner;
    double nn = glm::dot(n, n);
    // Cramer's rule in the plane: a = (q x v).n / |n|^2, b = (u x q).n / |n|^2.
    double a = glm::dot(glm::cross(q, r.edge_v), n) / nn;
    double b = glm::dot(glm::cross(r.edge_u, q), n) / nn;
    if (a < 0.0 || a > 1.0 || b < 0.0 || b > 1.0) return std::nullopt;
    return SurfaceHit{t, n / std::sqrt(nn), {a, b}};
}

}  // namespace lancer::cpu

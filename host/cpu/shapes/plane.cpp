// Ray/infinite plane: (o + t d - p) . n = 0.
#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {

std::optional<SurfaceHit> intersect(const Plane& p, const Ray& ray, double t_min, double t_max) {
    double denom = glm::dot(p.normal, ray.dir);
    if (denom == 0.0) return std::nullopt;  // parallel, including a ray lying in the plane
    double t = glm::dot(p.point - ray.origin, p.normal) / denom;
    if (t <= t_min || t >= t_max) return std::nullopt;
    return SurfaceHit{t, p.normal};
}

// Planar: world distances along the plane's texture axes from its point.
glm::dvec2 texture_uv(const Plane& p, const dvec3& point) {
    dvec3 d = point - p.point;
    return {glm::dot(d, p.u_axis), glm::dot(d, p.v_axis)};
}

}  // namespace lancer::cpu

// An object's intersection: its shape's, through its placement where the shape keeps its own
// coordinates (an ellipsoid, a turned box).
#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {

std::optional<SurfaceHit> intersect(const Object& o, const Ray& ray, double t_min, double t_max) {
    auto shape_hit = [&](const Ray& r, double lo, double hi) {
        return std::visit([&](const auto& shape) { return intersect(shape, r, lo, hi); }, o.shape);
    };
    if (!o.placement || !o.placement->shape_in_object_space) return shape_hit(ray, t_min, t_max);
    const Placement& placed = *o.placement;
    // The shapes take unit directions: t in the object's units is k times the world's.
    const dvec3 d = placed.object_direction(ray.dir);
    const double k = glm::length(d);
    std::optional<SurfaceHit> h = shape_hit(Ray{placed.object_point(ray.origin), d / k}, t_min * k, t_max * k);
    if (h) {
        h->t = std::min(h->t / k, t_max);
        h->normal = placed.world_normal(h->normal);
    }
    return h;
}

}  // namespace lancer::cpu

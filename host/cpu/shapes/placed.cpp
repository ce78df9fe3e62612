// An object's intersection: its shape's, through its placement where the shape keeps its own
// coordinates (an ellipsoid, a turned box).
#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {

Ray shape_ray(const Object& o, const Ray& ray, double& k) {
    k = 1.0;
    if (!o.placement || !o.placement->shape_in_object_space) return ray;
    // The shapes take unit directions: t in the object's units is k times the world's.
    const dvec3 d = o.placement->object_direction(ray.dir);
    k = glm::length(d);
    return Ray{o.placement->object_point(ray.origin), d / k};
}

std::optional<SurfaceHit> intersect(const Object& o, const Ray& ray, double t_min, double t_max) {
    double k;
    const Ray r = shape_ray(o, ray, k);
    std::optional<SurfaceHit> h = std::visit([&](const auto& shape) { return intersect(shape, r, t_min * k, t_max * k); }, o.shape);
    if (h && o.placement && o.placement->shape_in_object_space) {
        h->t = std::min(h->t / k, t_max);
        h->normal = o.placement->world_normal(h->normal);
    }
    return h;
}

}  // namespace lancer::cpu

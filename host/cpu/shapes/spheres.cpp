// Ray/sphere set for the CPU reference: the set's own tree (SphereCloud::tree), then each
// candidate sphere as sphere.cpp's, in double from the file's float centres and radii. Twin of
// shaders/shapes/spheres.glsl (written apart: that one runs in float over the GPU's BVH).
#include <glm/geometric.hpp>

#include "cpu/shapes/element_walk.hpp"
#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

Sphere element(const SphereSet& s, int sphere) {
    const glm::vec4& e = s.cloud->spheres()[static_cast<std::size_t>(sphere)];
    return Sphere{dvec3(e), double(e.w)};
}

}  // namespace

std::optional<SurfaceHit> intersect(const SphereSet& s, const Ray& ray, double t_min, double t_max) {
    const auto& spheres = s.cloud->spheres();
    std::optional<double> best;
    std::uint32_t best_sphere = 0;
    double reach = t_max;
    walk_element_tree(s.cloud->tree(), ray, reach, [&](std::uint32_t i, double& reach) {
        const auto t = sphere_hit_t(dvec3(spheres[i]), double(spheres[i].w), ray, t_min, reach);
        if (!t) return;
        best = reach = *t;
        best_sphere = i;
    });
    if (!best) return std::nullopt;
    const Sphere hit = element(s, static_cast<int>(best_sphere));
    return SurfaceHit{*best, (ray.origin + *best * ray.dir - hit.center) / hit.radius, glm::dvec2(0.0),
                      static_cast<int>(best_sphere)};
}

glm::dvec2 sphere_set_texture_uv(const SphereSet& s, int sphere, const dvec3& p) { return texture_uv(element(s, sphere), p); }

}  // namespace lancer::cpu

#include "cpu/tracer.hpp"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

// Below this remaining weight a reflection cannot change the 8-bit result (as the shader).
constexpr double kMinWeight = 1.0 / 1024.0;

dvec3 mirror(const dvec3& d, const dvec3& n) { return d - 2.0 * glm::dot(d, n) * n; }

}  // namespace

dvec3 pigment_at(const Material& m, const dvec3& p) {
    if (!m.checker) return m.color;
    // First colour where floor(x)+floor(y)+floor(z) is even; the bias keeps a floor lying on an
    // integer plane on one side of it despite rounding.
    dvec3 cell = glm::floor(p / m.checker->size + 1e-4);
    long long parity = static_cast<long long>(cell.x + cell.y + cell.z) & 1;
    return parity == 0 ? m.checker->color_a : m.checker->color_b;
}

bool Tracer::closest_hit(const Ray& ray, double t_min, double t_max, Hit& hit) const {
    hit.object = nullptr;
    hit.t = t_max;
    for (const Object& object : scene_.objects) {
        auto h = std::visit([&](const auto& shape) { return intersect(shape, ray, t_min, hit.t); }, object.shape);
        if (h) {
            hit.t = h->t;
            hit.normal = h->normal;
            hit.uv = h->uv;
            hit.part = h->part;
            hit.object = &object;
        }
    }
    return hit.object != nullptr;
}

bool Tracer::occluded(const Ray& ray, double t_min, double t_max) const {
    for (const Object& object : scene_.objects) {
        auto h = std::visit([&](const auto& shape) { return intersect(shape, ray, t_min, t_max); }, object.shape);
        if (h) return true;
    }
    return false;
}

dvec3 Tracer::shade_local(const Material& m, const dvec3& p, const dvec3& n, const dvec3& view_dir,
                          double& rays) const {
    dvec3 pigment = pigment_at(m, p);
    dvec3 color = m.ambient * pigment * scene_.ambient;
    dvec3 mirrored = mirror(view_dir, n);
    dvec3 origin = p + ray_offset(p) * n;  // shadow rays start here; shading uses p itself
    for (const PointLight& light : scene_.lights) {
        dvec3 l = glm::normalize(light.position - p);
        double n_dot_l = glm::dot(n, l);
        if (n_dot_l <= 0.0) continue;  // the light is behind the surface
        rays += 1.0;
        dvec3 to_light = light.position - origin;
        double dist = glm::length(to_light);
        if (occluded({origin, to_light / dist}, 0.0, dist)) continue;
        color += m.diffuse * n_dot_l * pigment * light.color;
        double r_dot_l = glm::dot(mirrored, l);
        if (r_dot_l > 0.0 && m.specular > 0.0) color += m.specular * std::pow(r_dot_l, m.shininess) * light.color;
    }
    return color;
}

dvec3 Tracer::trace(Ray ray, double& rays) const {
    dvec3 color(0.0);
    dvec3 weight(1.0);
    for (int depth = 0; depth <= scene_.render.max_depth; ++depth) {
        rays += 1.0;
        Hit hit;
        if (!closest_hit(ray, 0.0, std::numeric_limits<double>::infinity(), hit)) {
            return color + weight * scene_.render.background;
        }
        dvec3 p = ray.origin + hit.t * ray.dir;
        dvec3 n = glm::dot(hit.normal, ray.dir) > 0.0 ? -hit.normal : hit.normal;  // two-sided
        const Material& m = scene_.materials[hit.object->material];
        color += weight * (1.0 - m.reflection) * shade_local(m, p, n, ray.dir, rays);
        weight *= m.reflection;
        if (std::max({weight.r, weight.g, weight.b}) < kMinWeight) return color;
        ray = {p + ray_offset(p) * n, mirror(ray.dir, n)};
    }
    return color;  // past max_depth the reflected ray contributes black
}

}  // namespace lancer::cpu

#include "cpu/tracer.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>

#include "accel/shape_bounds.hpp"
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
    // The parity by fmod, not by converting to an integer: a checker much finer than the scene
    // (size 1e-12 at 1e3) has cell numbers beyond any integer type.
    dvec3 cell = glm::floor(p / m.checker->size + 1e-4);
    bool odd = std::fmod(std::abs(cell.x + cell.y + cell.z), 2.0) == 1.0;
    return odd ? m.checker->color_b : m.checker->color_a;
}

Tracer::Tracer(const Scene& scene, Acceleration acceleration) : scene_(scene) {
    std::vector<Aabb> boxes;
    for (const Object& object : scene.objects) {
        std::optional<Aabb> box;
        if (acceleration == Acceleration::Bvh) box = shape_bounds(object.shape);
        if (box) {
            bounded_.push_back(&object);
            boxes.push_back(*box);
        } else {
            unbounded_.push_back(&object);
        }
    }
    Bvh bvh = build_bvh(boxes);
    std::vector<const Object*> ordered;
    for (std::uint32_t i : bvh.order) ordered.push_back(bounded_[i]);
    bounded_ = std::move(ordered);
    nodes_ = std::move(bvh.nodes);
}

namespace {

// Entry distance of the ray into the box within [0, t_max], or nothing.
std::optional<double> box_entry(const Aabb& b, const Ray& ray, const dvec3& inv_dir, double t_max) {
    double enter = 0.0, leave = t_max;
    for (int a = 0; a < 3; ++a) {
        double t0 = (b.lo[a] - ray.origin[a]) * inv_dir[a];
        double t1 = (b.hi[a] - ray.origin[a]) * inv_dir[a];
        if (std::isnan(t0) || std::isnan(t1)) continue;  // origin on a slab plane of a parallel ray
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
    }
    if (enter > leave) return std::nullopt;
    return enter;
}

}  // namespace

template <typename Visit, typename TMax>
void Tracer::for_each_candidate(const Ray& ray, TMax t_max, Visit visit) const {
    for (const Object* object : unbounded_)
        if (!visit(*object)) return;
    if (nodes_.empty()) return;
    dvec3 inv_dir = 1.0 / ray.dir;
    if (!box_entry(nodes_[0].box, ray, inv_dir, t_max())) return;
    std::vector<std::pair<std::uint32_t, double>> stack;
    stack.reserve(64);
    stack.emplace_back(0u, 0.0);
    while (!stack.empty()) {
        auto [index, entry] = stack.back();
        stack.pop_back();
        if (entry > t_max()) continue;
        const BvhNode& node = nodes_[index];
        if (node.leaf()) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
                if (!visit(*bounded_[i])) return;
            continue;
        }
        auto near_t = box_entry(nodes_[node.first].box, ray, inv_dir, t_max());
        auto far_t = box_entry(nodes_[node.first + 1].box, ray, inv_dir, t_max());
        std::uint32_t near_child = node.first, far_child = node.first + 1;
        if (far_t && (!near_t || *far_t < *near_t)) {
            std::swap(near_t, far_t);
            std::swap(near_child, far_child);
        }
        if (far_t) stack.emplace_back(far_child, *far_t);
        if (near_t) stack.emplace_back(near_child, *near_t);  // popped first
    }
}

bool Tracer::closest_hit(const Ray& ray, double t_min, double t_max, Hit& hit) const {
    hit.object = nullptr;
    hit.t = t_max;
    for_each_candidate(ray, [&] { return hit.t; }, [&](const Object& object) {
        auto h = std::visit([&](const auto& shape) { return intersect(shape, ray, t_min, hit.t); }, object.shape);
        if (h) {
            hit.t = h->t;
            hit.normal = h->normal;
            hit.uv = h->uv;
            hit.part = h->part;
            hit.object = &object;
        }
        return true;
    });
    return hit.object != nullptr;
}

bool Tracer::occluded(const Ray& ray, double t_min, double t_max) const {
    bool blocked = false;
    for_each_candidate(ray, [&] { return t_max; }, [&](const Object& object) {
        auto h = std::visit([&](const auto& shape) { return intersect(shape, ray, t_min, t_max); }, object.shape);
        blocked = h.has_value();
        return !blocked;
    });
    return blocked;
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

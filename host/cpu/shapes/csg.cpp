// CSG for the CPU reference (twin of shaders/shapes/csg.glsl, written apart): each leaf is a
// convex solid or a half-space, inside along the ray on one interval (from its first hit from
// -infinity to the first of the reversed ray); the combination's surface is the first end of an interval, beyond
// t_min, where the program's value changes. Comparing ends, not counting crossings, stays exact
// where a ray grazes a leaf (an interval of no length changes nothing).
#include <array>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Interval {
    double in = kInf, out = -kInf;  // inside for in < t < out; none where in >= out
};

// A half-space: inside behind the plane's normal, on the side of the crossing the ray comes from
// or goes to.
Interval half_space(const Object& leaf, const Plane& plane, const Ray& ray) {
    dvec3 normal = plane.normal, point = plane.point;
    if (leaf.placement && leaf.placement->shape_in_object_space) {
        normal = leaf.placement->world_normal(plane.normal);
        point = dvec3(leaf.placement->to_world * glm::dvec4(plane.point, 1.0));
    }
    const double along = glm::dot(ray.dir, normal), height = glm::dot(ray.origin - point, normal);
    if (along == 0.0) return height < 0.0 ? Interval{-kInf, kInf} : Interval{};
    const double t = -height / along;
    return along > 0.0 ? Interval{-kInf, t} : Interval{t, kInf};
}

// The exit of a convex solid is the entry of the reversed ray: no second search from the entry,
// whose rounding could find the entry again or step past a close exit.
Ray reversed(const Ray& ray) { return Ray{ray.origin, -ray.dir}; }

Interval inside_along(const Object& leaf, const Ray& ray) {
    if (const auto* plane = std::get_if<Plane>(&leaf.shape)) return half_space(leaf, *plane, ray);
    const auto in = intersect(leaf, ray, -kInf, kInf);
    const auto out = intersect(leaf, reversed(ray), -kInf, kInf);
    return in && out ? Interval{in->t, -out->t} : Interval{};  // in >= out: a touching ray, no length
}

bool value(const Csg& c, const std::array<Interval, CSG_MAX_LEAVES>& inside, double t, bool after) {
    std::uint64_t stack = 0;
    for (std::uint32_t op : c.program) {
        const std::uint32_t kind = op & 15u;
        if (kind == CSG_LEAF) {
            const Interval& i = inside[op >> 4];
            const bool in = after ? (i.in <= t && t < i.out) : (i.in < t && t <= i.out);
            stack = stack << 1 | (in ? 1u : 0u);
        } else if (kind == CSG_NOT) {
            stack ^= 1u;
        } else {
            const std::uint64_t b = stack & 1u, a = (stack >> 1) & 1u;
            stack = (stack >> 2) << 1 | (kind == CSG_AND ? (a & b) : kind == CSG_OR ? (a | b) : (a & (b ^ 1u)));
        }
    }
    return (stack & 1u) != 0;
}

}  // namespace

std::optional<SurfaceHit> intersect(const Csg& c, const Ray& ray, double t_min, double t_max) {
    const std::size_t n = c.leaves.size();
    std::array<Interval, CSG_MAX_LEAVES> inside{};
    for (std::size_t k = 0; k < n; ++k) inside[k] = inside_along(c.leaves[k], ray);
    // The ends in (t_min, t_max), nearest first: where the value just before differs from just after.
    double t = t_min;
    for (;;) {
        double next = t_max;
        std::size_t leaf = n;
        bool entering = false;
        for (std::size_t k = 0; k < n; ++k) {
            const Interval& i = inside[k];
            if (!(i.in < i.out)) continue;
            if (i.in > t && i.in < next) next = i.in, leaf = k, entering = true;
            if (i.out > t && i.out < next) next = i.out, leaf = k, entering = false;
        }
        if (leaf == n) return std::nullopt;
        if (value(c, inside, next, false) != value(c, inside, next, true)) {
            // The leaf's own hit there, for its normal and (u, v): its entry, or its exit.
            const Object& hit_leaf = c.leaves[leaf];
            const bool exit = !entering && !std::holds_alternative<Plane>(hit_leaf.shape);
            std::optional<SurfaceHit> h = intersect(hit_leaf, exit ? reversed(ray) : ray, -kInf, kInf);
            if (!h) return std::nullopt;  // cannot happen: the interval came from these calls
            h->t = next;
            h->part = static_cast<int>(leaf);
            return h;
        }
        t = next;
    }
}

}  // namespace lancer::cpu

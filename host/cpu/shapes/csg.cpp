// CSG for the CPU reference (twin of shaders/shapes/csg.glsl, written apart): a leaf that is a
// convex solid or a half-space is inside along the ray on one interval (from its first hit from
// -infinity to the first of the reversed ray); a closed leaf that is not convex (a torus, an
// implicit surface) on the stretches between its roots along the whole line where f < 0 at
// their middle; a surface that closes a solid (a closed mesh, a Bezier or parametric surface
// declared closed) between the roots where it enters and leaves, told by its normal's side. The
// combination's surface is the first end of an interval, beyond t_min, where the program's value
// changes. Comparing ends, not counting crossings, stays exact where a ray grazes a leaf (an
// interval of no length changes nothing).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"
#include "scene/shape_bounds.hpp"

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

// A closed leaf that is not convex: its intervals inside along the line, in order, each the
// stretches between consecutive roots whose middle is inside, adjacent ones joined (a ray
// touching the surface from inside). Before the first root and after the last it is outside.
std::vector<Interval> walked_inside(const Object& leaf, const Ray& ray) {
    double k;  // t in the shape's coordinates over the world's
    const Ray r = shape_ray(leaf, ray, k);
    auto walk = [&](const auto& shape) {
        const std::vector<double> roots = roots_on_line(shape, r);
        std::vector<Interval> spans;
        for (std::size_t i = 0; i + 1 < roots.size(); ++i) {
            const double a = roots[i], b = roots[i + 1];
            if (!inside(shape, r.origin + (0.5 * (a + b)) * r.dir)) continue;
            if (!spans.empty() && spans.back().out == a / k) spans.back().out = b / k;
            else spans.push_back(Interval{a / k, b / k});
        }
        return spans;
    };
    if (const auto* torus = std::get_if<Torus>(&leaf.shape)) return walk(*torus);
    if (const auto* blob = std::get_if<Blob>(&leaf.shape)) return walk(*blob);
    if (const auto* sor = std::get_if<Sor>(&leaf.shape)) return walk(*sor);
    if (const auto* prism = std::get_if<Prism>(&leaf.shape)) return walk(*prism);
    if (const auto* lathe = std::get_if<Lathe>(&leaf.shape)) return walk(*lathe);
    return walk(std::get<ImplicitObject>(leaf.shape));
}

// The line's stretch through a box grown by a millionth of its size, or an empty one.
std::pair<double, double> line_through(const Aabb& box, const Ray& ray) {
    const dvec3 pad(1e-6 * glm::length(box.hi - box.lo));
    const dvec3 lo = box.lo - pad, hi = box.hi + pad;
    double t0 = -kInf, t1 = kInf;
    for (int i = 0; i < 3; ++i) {
        if (ray.dir[i] == 0.0) {
            if (ray.origin[i] < lo[i] || ray.origin[i] > hi[i]) return {kInf, -kInf};
            continue;
        }
        const double a = (lo[i] - ray.origin[i]) / ray.dir[i], b = (hi[i] - ray.origin[i]) / ray.dir[i];
        t0 = std::max(t0, std::min(a, b));
        t1 = std::min(t1, std::max(a, b));
    }
    return {t0, t1};
}

// A surface that closes a solid (SHAPE_ORIENTED): its intervals inside, from its crossings. An
// entry while inside or an exit while outside (a touching point, a root found twice) changes
// nothing, and an entry never left (an exit lost) is dropped.
std::vector<Interval> crossed_inside(const Object& leaf, const Ray& ray) {
    double k;
    const Ray r = shape_ray(leaf, ray, k);
    const std::pair<double, double> span = line_through(*shape_bounds(leaf.shape), r);
    const double t0 = span.first, length = span.second - span.first;
    if (!(length >= 0.0)) return {};
    // The searches take t >= 0 (a mesh's tree walk): from the line's entry into the box, then.
    const Ray from{r.origin + t0 * r.dir, r.dir};
    std::vector<LineCrossing> crossings = std::visit(
        [&](const auto& shape) -> std::vector<LineCrossing> {
            if constexpr (requires { crossings_on_line(shape, from, 0.0, length); })
                return crossings_on_line(shape, from, 0.0, length);
            return {};  // not SHAPE_ORIENTED: never called
        },
        leaf.shape);
    for (LineCrossing& c : crossings) c.t += t0;
    std::vector<Interval> spans;
    bool in = false;
    for (const LineCrossing& c : crossings) {
        if (in == !c.leaving) continue;
        in = !c.leaving;
        if (!in) spans.back().out = c.t / k;
        else if (!spans.empty() && spans.back().out == c.t / k) spans.back().out = kInf;  // adjacent: joined
        else spans.push_back(Interval{c.t / k, kInf});
    }
    if (in) spans.pop_back();
    return spans;
}

bool walked(const Object& leaf) {
    const std::uint32_t type = shape_type(leaf.shape);
    return shape_has(type, SHAPE_CLOSED) || shape_has(type, SHAPE_ORIENTED);
}

// walked_inside (and the GPU's leaf_inside, shaders/scene.glsl) know these closed shapes.
constexpr bool closed_shapes_are_known() {
    for (std::uint32_t t = 0; t < SHAPE_COUNT; ++t)
        if (shape_has(t, SHAPE_CLOSED) != (t == SHAPE_TORUS || t == SHAPE_IMPLICIT || t == SHAPE_BLOB || t == SHAPE_SOR ||
                                         t == SHAPE_PRISM || t == SHAPE_LATHE))
            return false;
    return true;
}
static_assert(closed_shapes_are_known());

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
    std::array<Interval, CSG_MAX_LEAVES> inside{};       // each leaf's interval now
    std::array<std::vector<Interval>, CSG_MAX_LEAVES> later;  // a walked leaf's after it, last first
    for (std::size_t k = 0; k < n; ++k) {
        if (!walked(c.leaves[k])) {
            inside[k] = inside_along(c.leaves[k], ray);
            continue;
        }
        later[k] = shape_has(shape_type(c.leaves[k].shape), SHAPE_ORIENTED) ? crossed_inside(c.leaves[k], ray)
                                                                             : walked_inside(c.leaves[k], ray);
        std::reverse(later[k].begin(), later[k].end());
        while (!later[k].empty() && later[k].back().out <= t_min) later[k].pop_back();
        if (!later[k].empty()) inside[k] = later[k].back(), later[k].pop_back();
    }
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
        const Object& hit_leaf = c.leaves[leaf];
        if (value(c, inside, next, false) != value(c, inside, next, true)) {
            // The leaf's own hit there, for its normal and (u, v): a convex solid's entry or its
            // exit (the reversed ray's entry); a walked leaf's root there.
            std::optional<SurfaceHit> h;
            if (walked(hit_leaf)) {
                h = intersect(hit_leaf, ray, next - 1e-9 * (1.0 + std::abs(next)), kInf);
            } else {
                const bool exit = !entering && !std::holds_alternative<Plane>(hit_leaf.shape);
                h = intersect(hit_leaf, exit ? reversed(ray) : ray, -kInf, kInf);
            }
            if (!h) return std::nullopt;  // cannot happen: the interval came from these calls
            h->t = next;
            h->part = static_cast<int>(leaf);
            return h;
        }
        if (!entering && walked(hit_leaf)) {  // past a walked leaf's interval: its next one
            inside[leaf] = later[leaf].empty() ? Interval{} : later[leaf].back();
            if (!later[leaf].empty()) later[leaf].pop_back();
        }
        t = next;
    }
}

}  // namespace lancer::cpu

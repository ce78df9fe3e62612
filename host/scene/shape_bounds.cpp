#include "scene/shape_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace lancer {
namespace {

struct BoundsOf {
    std::optional<Aabb> operator()(const Sphere& s) const { return Aabb{s.center - s.radius, s.center + s.radius}; }
    std::optional<Aabb> operator()(const Plane&) const { return std::nullopt; }
    std::optional<Aabb> operator()(const Rectangle& r) const {
        Aabb b;
        for (double a : {0.0, 1.0})
            for (double c : {0.0, 1.0}) b.extend(r.corner + a * r.edge_u + c * r.edge_v);
        return b;
    }
    std::optional<Aabb> operator()(const Box& b) const { return Aabb{b.min, b.max}; }
    // A circle of radius R about c in the plane across unit n reaches R sqrt(1 - n_i^2) along
    // axis i; widened by a few roundings of R so that rounding never leaves its rim outside.
    std::optional<Aabb> operator()(const Disc& d) const {
        dvec3 reach;
        for (int i = 0; i < 3; ++i) reach[i] = d.radius * (std::sqrt(std::max(0.0, 1.0 - d.normal[i] * d.normal[i])) + 1e-15);
        return Aabb{d.center - reach, d.center + reach};
    }
    // The hull of the two end circles: each reaches r sqrt(1 - a_i^2) along axis i about its
    // centre (a the unit axis), widened as the disc's; the side between them is their convex hull.
    std::optional<Aabb> operator()(const Cone& c) const {
        const dvec3 a = glm::normalize(c.cap - c.base);
        Aabb box;
        for (int i = 0; i < 3; ++i) {
            const double across = std::sqrt(std::max(0.0, 1.0 - a[i] * a[i])) + 1e-15;
            const double rb = c.base_radius * across, rc = c.cap_radius * across;
            box.lo[i] = std::min(c.base[i] - rb, c.cap[i] - rc);
            box.hi[i] = std::max(c.base[i] + rb, c.cap[i] + rc);
        }
        return box;
    }
    // The tube's centre circle (radius R across unit a) reaches R sqrt(1 - a_i^2) along axis i and
    // the tube r beyond it; widened by a few roundings, as the disc's.
    std::optional<Aabb> operator()(const Torus& o) const {
        dvec3 reach;
        for (int i = 0; i < 3; ++i)
            reach[i] = (o.major_radius * std::sqrt(std::max(0.0, 1.0 - o.axis[i] * o.axis[i])) + o.minor_radius) * (1.0 + 1e-15);
        return Aabb{o.center - reach, o.center + reach};
    }
    std::optional<Aabb> operator()(const Csg& c) const { return Aabb{c.lo, c.hi}; }
    std::optional<Aabb> operator()(const Blob& o) const { return Aabb{o.lo, o.hi}; }
    std::optional<Aabb> operator()(const Sor& o) const {  // its own coordinates (it is always placed)
        return Aabb{dvec3(-o.r_max, o.segments.front().y0, -o.r_max), dvec3(o.r_max, o.segments.back().y1, o.r_max)};
    }
    std::optional<Aabb> operator()(const Prism& o) const {  // its own coordinates (it is always placed)
        if (!o.conic) return Aabb{dvec3(o.lo.x, o.y0, o.lo.y), dvec3(o.hi.x, o.y1, o.hi.y)};
        Aabb box;  // the outline's box scaled by each end's height (the ends' boxes hold the copies between)
        for (double y : {o.y0, o.y1}) {
            box.extend(dvec3(o.lo.x * y, y, o.lo.y * y));
            box.extend(dvec3(o.hi.x * y, y, o.hi.y * y));
        }
        return box;
    }
    std::optional<Aabb> operator()(const Lathe& o) const {  // its own coordinates (it is always placed)
        return Aabb{dvec3(-o.r_max, o.y_lo, -o.r_max), dvec3(o.r_max, o.y_hi, o.r_max)};
    }
    std::optional<Aabb> operator()(const Superellipsoid&) const { return Aabb{dvec3(-1.0), dvec3(1.0)}; }  // its own coordinates
    std::optional<Aabb> operator()(const Mesh& m) const { return Aabb{m.geometry->lo(), m.geometry->hi()}; }  // the file's
    std::optional<Aabb> operator()(const SphereSet& s) const { return Aabb{s.cloud->lo(), s.cloud->hi()}; }
    std::optional<Aabb> operator()(const ParametricObject& p) const { return Aabb{p.bounds_lo, p.bounds_hi}; }
    std::optional<Aabb> operator()(const ImplicitObject& o) const {
        Aabb b;
        surface::implicit_world_bounds(*o.surface, b.lo, b.hi);
        return b;
    }
    std::optional<Aabb> operator()(const BezierSurface& s) const {
        Aabb b;
        for (const auto& patch : s.patches) {
            surface::PatchBounds pb = surface::bounds(patch);
            b.extend(pb.min);
            b.extend(pb.max);
        }
        return b;
    }
};

}  // namespace

std::optional<Aabb> shape_bounds(const Shape& shape) { return std::visit(BoundsOf{}, shape); }

std::optional<Aabb> csg_bounds(const std::vector<Object>& leaves, const std::vector<std::uint32_t>& program) {
    std::vector<std::optional<Aabb>> stack;  // nullopt: everywhere
    for (std::uint32_t op : program) {
        if ((op & 15u) == CSG_LEAF) {
            stack.push_back(object_bounds(leaves.at(op >> 4)));
            continue;
        }
        if (op == CSG_NOT) {
            stack.back() = std::nullopt;  // the outside of a bounded solid is unbounded
            continue;
        }
        const std::optional<Aabb> b = stack.back();
        stack.pop_back();
        std::optional<Aabb>& a = stack.back();
        if (op == CSG_OR) {
            if (a && b) a->extend(*b);
            else a = std::nullopt;
        } else if (op == CSG_AND) {
            if (!a) a = b;
            else if (b) a = Aabb{glm::max(a->lo, b->lo), glm::min(a->hi, b->hi)};
        }  // CSG_AND_NOT: within a
    }
    return stack.at(0);
}

std::optional<Aabb> object_bounds(const Object& o) {
    std::optional<Aabb> box = shape_bounds(o.shape);
    if (!box || !o.placement || !o.placement->shape_in_object_space) return box;
    const glm::dmat4& m = o.placement->to_world;
    Aabb world;
    if (const auto* s = std::get_if<Sphere>(&o.shape)) {
        // An ellipsoid c + L u, |u| <= r, reaches r |row i of L| along axis i.
        const dvec3 c(m * glm::dvec4(s->center, 1.0));
        dvec3 reach;
        for (int i = 0; i < 3; ++i) reach[i] = s->radius * std::hypot(m[0][i], m[1][i], m[2][i]) * (1.0 + 1e-15);
        return Aabb{c - reach, c + reach};
    }
    for (int corner = 0; corner < 8; ++corner) {
        const dvec3 p((corner & 1) ? box->hi.x : box->lo.x, (corner & 2) ? box->hi.y : box->lo.y,
                      (corner & 4) ? box->hi.z : box->lo.z);
        world.extend(dvec3(m * glm::dvec4(p, 1.0)));
    }
    // Widened by a few roundings of its size, as the disc's: the corners' products round.
    const dvec3 pad = 1e-15 * (glm::abs(world.lo) + glm::abs(world.hi));
    return Aabb{world.lo - pad, world.hi + pad};
}

void prepare_blob(Blob& o) {
    o.lo = dvec3(std::numeric_limits<double>::infinity());
    o.hi = -o.lo;
    for (const BlobComponent& k : o.components) {
        if (!(k.strength > 0.0)) continue;
        o.lo = glm::min(o.lo, glm::min(k.a, k.b) - k.radius);
        o.hi = glm::max(o.hi, glm::max(k.a, k.b) + k.radius);
    }
    o.tree = std::make_shared<const ElementTree>(
        build_element_tree(static_cast<std::uint32_t>(o.components.size()), [&](std::uint32_t i, dvec3& lo, dvec3& hi) {
            const BlobComponent& k = o.components[i];
            lo = glm::min(lo, glm::min(k.a, k.b) - k.radius);
            hi = glm::max(hi, glm::max(k.a, k.b) + k.radius);
        }));
}

}  // namespace lancer

#include "accel/shape_bounds.hpp"

#include <algorithm>
#include <cmath>

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
    // The tube's centre circle (radius R across unit a) reaches R sqrt(1 - a_i^2) along axis i and
    // the tube r beyond it; widened by a few roundings, as the disc's.
    std::optional<Aabb> operator()(const Torus& o) const {
        dvec3 reach;
        for (int i = 0; i < 3; ++i)
            reach[i] = (o.major_radius * std::sqrt(std::max(0.0, 1.0 - o.axis[i] * o.axis[i])) + o.minor_radius) * (1.0 + 1e-15);
        return Aabb{o.center - reach, o.center + reach};
    }
    std::optional<Aabb> operator()(const ParametricObject& p) const { return Aabb{p.bounds_lo, p.bounds_hi}; }
    std::optional<Aabb> operator()(const ImplicitObject& o) const {
        Aabb b;
        surface::implicit_world_bounds(o.surface, b.lo, b.hi);
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

}  // namespace lancer

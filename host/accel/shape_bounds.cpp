#include "accel/shape_bounds.hpp"

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

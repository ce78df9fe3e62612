#include "surface/parametric_cells.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "core/cancel.hpp"
#include "core/finite.hpp"
#include "surface/expr/program.hpp"
#include "surface/float_check.hpp"
#include "surface/surface_bounds.hpp"

namespace lancer::surface {
namespace {

constexpr int kPaddingUlps = 4;

struct Pending {
    Interval u, v;
    int depth;
};

double length(const IntervalVec3& a) {
    return std::sqrt(sqr(a.x.mag()) + sqr(a.y.mag()) + sqr(a.z.mag()));
}

double diagonal(const IntervalVec3& box) {
    return std::sqrt(sqr(box.x.width()) + sqr(box.y.width()) + sqr(box.z.width()));
}

bool is_finite(const IntervalVec3& box) { return box.x.is_finite() && box.y.is_finite() && box.z.is_finite(); }

// |Su x Sv| >= kRegular |Su| |Sv| on the whole box: not only nonzero but well conditioned. (A
// sphere's pole cell in double has cos(v) >= 6e-17 > 0 there, "regular" in the strict sense
// only.)
constexpr double kRegular = 1e-3;

bool proved_regular(const BoxBounds& b) {
    if (!b.smooth) return false;
    Interval nx = b.Su.y * b.Sv.z - b.Su.z * b.Sv.y;
    Interval ny = b.Su.z * b.Sv.x - b.Su.x * b.Sv.z;
    Interval nz = b.Su.x * b.Sv.y - b.Su.y * b.Sv.x;
    double n2 = (sqr(nx) + sqr(ny) + sqr(nz)).lo;
    double su2 = sqr(b.Su.x.mag()) + sqr(b.Su.y.mag()) + sqr(b.Su.z.mag());
    double sv2 = sqr(b.Sv.x.mag()) + sqr(b.Sv.y.mag()) + sqr(b.Sv.z.mag());
    return n2 > 0.0 && n2 >= kRegular * kRegular * su2 * sv2;
}

// The diagonal of the world box of S sampled on a grid: the yardstick cells are measured by.
double surface_diagonal(const Program& program, const ParametricSurface& s) {
    constexpr int n = 32;
    dvec3 lo(kInf), hi(-kInf);
    bool any = false;
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            double p[3];
            evaluate_program(program, s.u0 + (s.u1 - s.u0) * i / n, s.v0 + (s.v1 - s.v0) * j / n, p);
            dvec3 w(s.to_world * glm::dvec4(p[0], p[1], p[2], 1.0));
            if (!all_finite(w)) continue;
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
            any = true;
        }
    }
    if (!any) throw UserError("the surface is not defined (or not finite) anywhere on its (u, v) domain");
    return glm::length(hi - lo);
}

void check_domain(const ParametricSurface& s) {
    if (!std::isfinite(s.u0) || !std::isfinite(s.u1) || !(s.u0 < s.u1))
        throw UserError(fmt::format("the u range [{}, {}] must be finite with u0 < u1", s.u0, s.u1));
    if (!std::isfinite(s.v0) || !std::isfinite(s.v1) || !(s.v0 < s.v1))
        throw UserError(fmt::format("the v range [{}, {}] must be finite with v0 < v1", s.v0, s.v1));
}

}  // namespace

std::vector<SurfaceCell> subdivide_surface(const ParametricSurface& s, const CellOptions& options) {
    check_domain(s);
    const Expr* xyz[] = {&s.x, &s.y, &s.z};
    const Program program = compile_program(xyz);
    const double reference = surface_diagonal(program, s);
    // The GPU evaluates the surface in float: where that strays from double by more than
    // rounding, the surface is refused; what rounding leaves is added to every box, so that the
    // boxes hold the surface the GPU draws as well as the exact one.
    const double float_error = check_float_evaluation(program, s);
    const glm::dmat3 linear(s.to_world);
    const double float_pad = 4.0 * float_error *
                             std::sqrt(glm::dot(linear[0], linear[0]) + glm::dot(linear[1], linear[1]) + glm::dot(linear[2], linear[2]));
    // A surface that is a single point still gets finite targets (its boxes are ulps wide).
    const double floor = 1e-12 * (1.0 + reference);
    const double target = std::max(options.max_size_fraction * reference, floor);
    const double regular_target = std::max(options.min_regular_fraction * reference, floor);

    std::vector<Pending> stack;
    const int g = std::max(1, options.initial_grid);
    for (int i = g - 1; i >= 0; --i) {
        for (int j = g - 1; j >= 0; --j) {
            // Neighbours share their boundary values exactly: both are computed by one formula.
            auto at = [g](double lo, double hi, int k) { return k == g ? hi : lo + (hi - lo) * k / g; };
            stack.push_back({{at(s.u0, s.u1, i), at(s.u0, s.u1, i + 1)}, {at(s.v0, s.v1, j), at(s.v0, s.v1, j + 1)}, 0});
        }
    }

    std::vector<SurfaceCell> cells;
    while (!stack.empty()) {
        throw_if_cancelled();  // a surface at the limits takes seconds: Ctrl-C must not wait for it
        if (cells.size() + stack.size() > options.max_cells)
            throw UserError(fmt::format(
                "the surface needs more than {} cells to be bounded tightly; simplify it or narrow its domain",
                options.max_cells));
        Pending p = stack.back();
        stack.pop_back();
        BoxBounds local = bound_surface(program, p.u, p.v);
        if (local.S.is_empty()) continue;  // no surface here: S is undefined on the whole cell
        IntervalVec3 box = world_bounds(local, program, s.to_world, p.u, p.v);
        if (box.is_empty()) continue;
        const bool finite = is_finite(box);
        const bool regular = proved_regular(local);
        const double size = diagonal(box);
        const bool split = !finite || size > target || (!regular && size > regular_target);
        if (split && p.depth < options.max_depth) {
            // Split the side that is longer on the surface (not in parameter units: a torus's
            // u side is several times its v side), so that cells become roughly square.
            double lu = p.u.width() * length(transform_vector(s.to_world, local.Su));
            double lv = p.v.width() * length(transform_vector(s.to_world, local.Sv));
            if (!std::isfinite(lu) || !std::isfinite(lv) || !local.smooth) {
                lu = p.u.width() / (s.u1 - s.u0);
                lv = p.v.width() / (s.v1 - s.v0);
            }
            if (lu >= lv) {
                double m = 0.5 * (p.u.lo + p.u.hi);
                stack.push_back({{m, p.u.hi}, p.v, p.depth + 1});
                stack.push_back({{p.u.lo, m}, p.v, p.depth + 1});
            } else {
                double m = 0.5 * (p.v.lo + p.v.hi);
                stack.push_back({p.u, {m, p.v.hi}, p.depth + 1});
                stack.push_back({p.u, {p.v.lo, m}, p.depth + 1});
            }
            continue;
        }
        if (!finite)
            throw UserError(fmt::format(
                "cannot bound the surface near (u, v) = ({:.6g}, {:.6g}): it may be unbounded there; narrow its domain",
                p.u.mid(), p.v.mid()));
        // The partials over the widened cell, for the GPU's Krawczyk test of the whole cell.
        auto widened = [](const Interval& x, double lo, double hi) {
            const double w = kCellBoundsInflation * x.width();
            return Interval{std::max(lo, x.lo - w), std::min(hi, x.hi + w)};
        };
        const BoxBounds around = bound_surface(program, widened(p.u, s.u0, s.u1), widened(p.v, s.v0, s.v1));
        const Interval unbounded{-kInf, kInf};
        const IntervalVec3 none{unbounded, unbounded, unbounded};
        const bool derivatives = around.smooth && is_finite(around.Su) && is_finite(around.Sv);
        SurfaceCell cell{p.u.lo, p.u.hi, p.v.lo, p.v.hi,
                         {down(box.x.lo - float_pad, kPaddingUlps), down(box.y.lo - float_pad, kPaddingUlps),
                          down(box.z.lo - float_pad, kPaddingUlps)},
                         {up(box.x.hi + float_pad, kPaddingUlps), up(box.y.hi + float_pad, kPaddingUlps),
                          up(box.z.hi + float_pad, kPaddingUlps)},
                         regular, float_pad, derivatives ? around.Su : none, derivatives ? around.Sv : none,
                         {none, none, none}, 4.0 * float_error};
        if (derivatives) cell.second = bound_second_partials(program, widened(p.u, s.u0, s.u1), widened(p.v, s.v0, s.v1));
        double centre[3];
        evaluate_program(program, p.u.mid(), p.v.mid(), centre);
        cell.centre_point = dvec3(centre[0], centre[1], centre[2]);
        cells.push_back(cell);
    }
    return cells;
}

}  // namespace lancer::surface

#include "surface/implicit_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <fmt/format.h>

namespace lancer::surface {
namespace {

bool regular(const dvec3& g) {
    const bool finite = std::isfinite(g.x) && std::isfinite(g.y) && std::isfinite(g.z);
    return finite && (g.x != 0.0 || g.y != 0.0 || g.z != 0.0);
}

// g / |g|, scaled by its largest component first: a gradient like (0, 1e-164, 1e-170) (f = y^17 z
// near y = 0) has a squared length below double's range, and normalize() would divide by 0.
dvec3 unit(dvec3 g) {
    g /= std::max({std::abs(g.x), std::abs(g.y), std::abs(g.z)});
    return glm::normalize(g);
}

}  // namespace

void ImplicitSurface::place(const glm::dmat4& m) {
    to_world = m;
    to_local = glm::inverse(m);
}

ImplicitPoint evaluate_implicit(const ImplicitSurface& s, const dvec3& p) {
    using D = Dual<double>;
    // Dual carries two partials: x and y in one pass, z in a second.
    const D xy[] = {D{p.x, 1.0, 0.0}, D{p.y, 0.0, 1.0}, D::constant(p.z)};
    const D z[] = {D::constant(p.x), D::constant(p.y), D{p.z, 1.0, 0.0}};
    D a, b;
    evaluate_program<D>(s.program, xy, &a);
    evaluate_program<D>(s.program, z, &b);
    return {a.v, {a.du, a.dv, b.du}};
}

dvec3 implicit_normal(const ImplicitSurface& s, const dvec3& world) {
    const glm::dmat3 normal_map = glm::transpose(glm::dmat3(s.to_local));
    const dvec3 local = dvec3(s.to_local * glm::dvec4(world, 1.0));
    const dvec3 diagonal = (s.box_hi - s.box_lo) / std::sqrt(3.0);
    for (double step : {0.0, 1e-9, 1e-7, 1e-5, 1e-3, 1e-2}) {
        dvec3 n = normal_map * evaluate_implicit(s, local + step * diagonal).gradient;
        if (regular(n)) return unit(n);
    }
    return {0.0, 0.0, 1.0};
}

bool proved_without_zero(const ImplicitSurface& s, int budget) { return proved_without_zero(s, s.box_lo, s.box_hi, budget); }

bool proved_without_zero(const ImplicitSurface& s, const dvec3& lo, const dvec3& hi, int budget) {
    struct Box {
        Interval axis[3];
    };
    std::vector<Box> boxes{{{{lo.x, hi.x}, {lo.y, hi.y}, {lo.z, hi.z}}}};
    const dvec3 size = hi - lo;
    while (!boxes.empty()) {
        Box box = boxes.back();
        boxes.pop_back();
        Interval f;
        evaluate_program<Interval>(s.program, box.axis, &f);
        if (f.is_empty() || f.lo > 0.0 || f.hi < 0.0) continue;
        if (--budget <= 0) return false;
        int split = 0;
        for (int k = 1; k < 3; ++k)
            if (box.axis[k].width() / size[k] > box.axis[split].width() / size[split]) split = k;
        Box low = box, high = box;
        low.axis[split].hi = high.axis[split].lo = box.axis[split].mid();
        boxes.push_back(low);
        boxes.push_back(high);
    }
    return true;
}

std::optional<dvec3> not_proved_positive_on_faces(const ImplicitSurface& s, int budget) {
    struct Piece {
        Interval axis[3];
    };
    const dvec3 size = s.box_hi - s.box_lo;
    for (int face = 0; face < 6; ++face) {
        const int fixed = face / 2;
        const double at = face % 2 == 0 ? s.box_lo[fixed] : s.box_hi[fixed];
        Piece whole{{{s.box_lo.x, s.box_hi.x}, {s.box_lo.y, s.box_hi.y}, {s.box_lo.z, s.box_hi.z}}};
        whole.axis[fixed] = Interval(at);
        std::vector<Piece> pieces{whole};
        while (!pieces.empty()) {
            Piece piece = pieces.back();
            pieces.pop_back();
            Interval f;
            evaluate_program<Interval>(s.program, piece.axis, &f);
            if (!f.is_empty() && f.lo > 0.0) continue;
            const dvec3 middle(piece.axis[0].mid(), piece.axis[1].mid(), piece.axis[2].mid());
            if (f.is_empty() || f.hi <= 0.0 || --budget <= 0) return middle;
            int split = fixed == 0 ? 1 : 0;
            for (int k = 0; k < 3; ++k)
                if (k != fixed && piece.axis[k].width() / size[k] > piece.axis[split].width() / size[split]) split = k;
            Piece low = piece, high = piece;
            low.axis[split].hi = high.axis[split].lo = piece.axis[split].mid();
            pieces.push_back(low);
            pieces.push_back(high);
        }
    }
    return std::nullopt;
}

void shrink_to_surface(const ImplicitSurface& s, dvec3& lo, dvec3& hi) {
    constexpr double kResolution = 1.0 / 64;  // of the box's size on that axis
    constexpr int kSlabBudget = 16;           // sub-boxes to prove one slab empty
    constexpr int kMaxSlabs = 2000;           // slabs tried in all: a bound on the work, never reached by a box of sane numbers
    const dvec3 original_lo = lo, original_hi = hi;
    int slabs = 0;
    for (bool moved = true; moved && slabs < kMaxSlabs;) {
        moved = false;
        for (int axis = 0; axis < 3; ++axis) {
            for (int side = 0; side < 2; ++side) {
                // The widest slab at this face that holds no zero, halving down to the resolution.
                for (double w = 0.5 * (hi[axis] - lo[axis]); w > kResolution * (hi[axis] - lo[axis]) && slabs < kMaxSlabs; ++slabs) {
                    dvec3 slab_lo = lo, slab_hi = hi;
                    if (side == 0) slab_hi[axis] = lo[axis] + w;
                    else slab_lo[axis] = hi[axis] - w;
                    double& face = side == 0 ? lo[axis] : hi[axis];
                    const double moved_to = side == 0 ? slab_hi[axis] : slab_lo[axis];
                    // A face that would not move (w below the coordinate's rounding) or pass the
                    // other one ends the search on this side.
                    if (moved_to == face || !(slab_lo[axis] < slab_hi[axis]) || !(lo[axis] < hi[axis])) break;
                    if (proved_without_zero(s, slab_lo, slab_hi, kSlabBudget)) {
                        face = moved_to;
                        moved = true;
                        w = std::min(w, 0.5 * (hi[axis] - lo[axis]));
                    } else {
                        w *= 0.5;
                    }
                }
            }
        }
    }
    const dvec3 margin = kResolution * (hi - lo);
    lo = glm::max(original_lo, lo - margin);
    hi = glm::min(original_hi, hi + margin);
}

glm::dvec2 implicit_texture_uv(const ImplicitSurface& s, const dvec3& p) {
    return {(p.x - s.box_lo.x) / (s.box_hi.x - s.box_lo.x), (p.y - s.box_lo.y) / (s.box_hi.y - s.box_lo.y)};
}

void implicit_world_bounds(const ImplicitSurface& s, dvec3& lo, dvec3& hi) {
    lo = dvec3(std::numeric_limits<double>::infinity());
    hi = -lo;
    for (int corner = 0; corner < 8; ++corner) {
        dvec3 c((corner & 1) ? s.box_hi.x : s.box_lo.x, (corner & 2) ? s.box_hi.y : s.box_lo.y,
                (corner & 4) ? s.box_hi.z : s.box_lo.z);
        dvec3 w = dvec3(s.to_world * glm::dvec4(c, 1.0));
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
    }
}

}  // namespace lancer::surface

namespace lancer::surface {

std::optional<std::string> degenerate_zero_set(const ImplicitSurface& s) {
    // f is 0 at a point where its outward-rounded interval value there holds 0: as far as
    // double's arithmetic can tell, whatever the scale of f's terms at that point.
    const auto zero_at = [&](const dvec3& p) {
        const Interval xyz[] = {p.x, p.y, p.z};
        Interval f;
        evaluate_program<Interval>(s.program, xyz, &f);
        return !f.is_empty() && f.contains(0.0);
    };
    // Cell centres of an n^3 grid (never on the box's faces), and an n^2 grid on each face.
    constexpr int n = 12;
    const dvec3 size = s.box_hi - s.box_lo;
    std::vector<char> grid(n * n * n);
    const auto at = [&](int i, int j, int k) { return grid[(i * n + j) * n + k] != 0; };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) grid[(i * n + j) * n + k] = zero_at(s.box_lo + size * (dvec3(i, j, k) + 0.5) / double(n));
    const auto face_is_zero = [&](int axis, int side) {
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) {
                dvec3 t(0.0);
                t[(axis + 1) % 3] = (a + 0.5) / n;
                t[(axis + 2) % 3] = (b + 0.5) / n;
                t[axis] = side;
                if (!zero_at(s.box_lo + size * t)) return false;
            }
        return true;
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side)
            if (face_is_zero(axis, side))
                return fmt::format("the function is 0 all over the box's face {} = {:g}: the surface lies on the box's "
                                   "boundary, where the clipping decides whether it is seen; make the box larger or "
                                   "smaller across it",
                                   "xyz"[axis], side ? s.box_hi[axis] : s.box_lo[axis]);
    for (int i = 1; i + 1 < n; ++i)
        for (int j = 1; j + 1 < n; ++j)
            for (int k = 1; k + 1 < n; ++k)
                if (at(i, j, k) && at(i - 1, j, k) && at(i + 1, j, k) && at(i, j - 1, k) && at(i, j + 1, k) &&
                    at(i, j, k - 1) && at(i, j, k + 1)) {
                    const dvec3 p = s.box_lo + size * (dvec3(i, j, k) + 0.5) / double(n);
                    return fmt::format("the function is 0 throughout a region of the box (at ({:g}, {:g}, {:g}) and "
                                       "all around it), not only on a surface: a solid of zeros has no surface in it "
                                       "to find; write a function that changes sign across the surface you mean",
                                       p.x, p.y, p.z);
                }
    return std::nullopt;
}

}  // namespace lancer::surface

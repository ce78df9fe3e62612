#include "gpu/packing/direction_grids.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

#include "gpu/packing/float_bounds.hpp"

namespace lancer::gpu {
namespace {

using glm::dvec3;

// A grid has at most this many columns and rows, and lists at most this many entries (8 bytes
// each); coarser where it would list more, and none where even one cell would.
constexpr double kMaxSide = 512;
constexpr std::size_t kMaxEntries = std::size_t(1) << 19;
// Cells this long on average (weighed by their length) are slower than the BVH.
constexpr double kMaxMeanList = 24.0;
// Boxes around the eye's plane are listed in every cell of its grid; more than this, no grid.
constexpr std::size_t kMaxEverywhere = 16;
// Cells are about a quarter of a typical box's extent across (2 to 12 measured within 3% on `many`).
constexpr double kCellsPerBox = 4.0;
// Boxes are padded by this share of their coordinates before they are projected (the GPU's float
// geometry is within a few ulps of the boxes' doubles), and footprints by this share of their
// projected coordinates (the shader's float projection of a direction).
constexpr double kBoxPad = 1e-5;
constexpr double kPrintPad = 1e-5;

struct Footprint {
    double u0, u1, v0, v1;
    float near;  // at most the distance from the grid's origin to the box
    uint index;
};

// Unit vectors u, v across `axis`, so that (axis, u, v) is orthonormal.
void across(const dvec3& axis, dvec3& u, dvec3& v) {
    dvec3 a = glm::abs(axis);
    dvec3 helper = a.x <= a.y && a.x <= a.z ? dvec3(1, 0, 0) : a.y <= a.z ? dvec3(0, 1, 0) : dvec3(0, 0, 1);
    u = glm::normalize(glm::cross(axis, helper));
    v = glm::cross(axis, u);
}

double max_abs(const dvec3& p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }

}  // namespace

DirectionGrid direction_grid(const dvec3& origin, std::span<const Aabb> boxes, const EyeView* view, DirectionGrids& out,
                             double slack, bool required) {
    DirectionGrid grid{};  // valid = 0: through the BVH
    // Every box a light's grid holds is listed at least once: more than its entries' limit can
    // never make a grid, found here before every box is projected (at 10^6 boxes 0.2 s a light).
    if (!view && !required && boxes.size() > kMaxEntries) return grid;
    dvec3 axis, u, v;
    if (view) {
        axis = glm::normalize(view->forward);
        u = glm::normalize(view->right);
        v = glm::normalize(view->up);
    } else {
        Aabb all;
        for (const Aabb& b : boxes) all.extend(b);
        if (all.empty()) return grid;
        axis = all.center() - origin;
        if (!(glm::length(axis) > 0.0)) return grid;
        axis = glm::normalize(axis);
        across(axis, u, v);
    }
    if (!std::isfinite(axis.x + axis.y + axis.z + u.x + u.y + u.z + v.x + v.y + v.z)) return grid;

    // The eye's window is its view (a little wider), known before any box is projected.
    const double view_u = view ? 1.01 * glm::length(view->right) + 1e-6 : 0.0;
    const double view_v = view ? 1.01 * glm::length(view->up) + 1e-6 : 0.0;
    std::vector<Footprint> prints;
    prints.reserve(std::min(boxes.size(), kMaxEntries + 1));  // at most one past the limit: never regrown
    std::vector<uint> everywhere;  // the eye's: boxes around its plane
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Aabb& b = boxes[i];
        const double pad = kBoxPad * std::max({1.0, max_abs(b.lo), max_abs(b.hi)});
        const dvec3 lo = b.lo - pad, hi = b.hi + pad;
        double z0 = INFINITY, z1 = -INFINITY, u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
        dvec3 corner[8];
        for (int c = 0; c < 8; ++c) {
            corner[c] = dvec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z) - origin;
            const double z = glm::dot(corner[c], axis);
            z0 = std::min(z0, z);
            z1 = std::max(z1, z);
        }
        const double distance = glm::length(glm::clamp(origin, lo, hi) - origin);
        const float near = round_down(distance * (1.0 - kBoxPad));
        if (!(z1 > 0.0)) {
            if (view) continue;  // behind the eye: no camera ray reaches it
            return grid;
        }
        if (!(z0 > 0.0)) {
            if (!view) return grid;  // the light is beside the boxes, not in front of them all
            everywhere.push_back(static_cast<uint>(i));
            prints.push_back({-INFINITY, INFINITY, -INFINITY, INFINITY, near, static_cast<uint>(i)});
            continue;
        }
        // A box wholly in front of the origin projects into the hull of its corners' projections.
        for (const dvec3& c : corner) {
            const double z = glm::dot(c, axis);
            const double cu = glm::dot(c, u) / z, cv = glm::dot(c, v) / z;
            u0 = std::min(u0, cu);
            u1 = std::max(u1, cu);
            v0 = std::min(v0, cv);
            v1 = std::max(v1, cv);
        }
        // The float projection's rounding, and a direction `slack` away: tan moves by (1 + tan^2) per radian.
        const double most = std::max({std::abs(u0), std::abs(u1), std::abs(v0), std::abs(v1)});
        const double m = kPrintPad * (1.0 + most) + slack * (1.0 + 2.0 * most * most);
        if (view && (u1 + m < -view_u || u0 - m > view_u || v1 + m < -view_v || v0 - m > view_v)) continue;  // out of view
        prints.push_back({u0 - m, u1 + m, v0 - m, v1 + m, near, static_cast<uint>(i)});
        // Each print is listed at least once: more than the entries' limit can make no grid.
        if (prints.size() > kMaxEntries && !required) return grid;
    }
    if (everywhere.size() > kMaxEverywhere && !required) return grid;

    // The window: the eye's view (a little wider), or everything the boxes cover.
    double wu0, wu1, wv0, wv1;
    if (view) {
        wu1 = view_u;
        wv1 = view_v;
        wu0 = -wu1;
        wv0 = -wv1;
    } else {
        wu0 = wv0 = INFINITY;
        wu1 = wv1 = -INFINITY;
        for (const Footprint& f : prints) {
            wu0 = std::min(wu0, f.u0);
            wu1 = std::max(wu1, f.u1);
            wv0 = std::min(wv0, f.v0);
            wv1 = std::max(wv1, f.v1);
        }
        const double m = kPrintPad * (1.0 + std::max({std::abs(wu0), std::abs(wu1), std::abs(wv0), std::abs(wv1)}));
        wu0 -= m;
        wu1 += m;
        wv0 -= m;
        wv1 += m;
    }
    if (!(wu1 > wu0 && wv1 > wv0) || !std::isfinite(wu0 + wu1 + wv0 + wv1)) return grid;
    // Clipped to the window; the eye's grid leaves out what lies outside its view.
    std::vector<double> extents;
    std::erase_if(prints, [&](Footprint& f) {
        f.u0 = std::max(f.u0, wu0);
        f.u1 = std::min(f.u1, wu1);
        f.v0 = std::max(f.v0, wv0);
        f.v1 = std::min(f.v1, wv1);
        return !(f.u0 <= f.u1 && f.v0 <= f.v1);
    });
    for (const Footprint& f : prints)
        if (std::isfinite(f.near) && (f.u1 - f.u0) < (wu1 - wu0)) extents.push_back(std::max(f.u1 - f.u0, f.v1 - f.v0));

    double cell = 0.0;
    if (!extents.empty()) {
        std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
        cell = extents[extents.size() / 2] / kCellsPerBox;
    }
    double columns = cell > 0.0 ? std::clamp(std::ceil((wu1 - wu0) / cell), 1.0, kMaxSide) : 1.0;
    double rows = cell > 0.0 ? std::clamp(std::ceil((wv1 - wv0) / cell), 1.0, kMaxSide) : 1.0;

    // The cells a footprint covers, widened by a thousandth of a cell for the shader's rounding.
    auto span = [&](const Footprint& f, double cols, double rws, int& i0, int& i1, int& j0, int& j1) {
        const double su = cols / (wu1 - wu0), sv = rws / (wv1 - wv0);
        i0 = static_cast<int>(std::clamp(std::floor((f.u0 - wu0) * su - 1e-3), 0.0, cols - 1));
        i1 = static_cast<int>(std::clamp(std::floor((f.u1 - wu0) * su + 1e-3), 0.0, cols - 1));
        j0 = static_cast<int>(std::clamp(std::floor((f.v0 - wv0) * sv - 1e-3), 0.0, rws - 1));
        j1 = static_cast<int>(std::clamp(std::floor((f.v1 - wv0) * sv + 1e-3), 0.0, rws - 1));
    };
    std::size_t total = 0;
    for (;;) {
        total = 0;
        for (const Footprint& f : prints) {
            int i0, i1, j0, j1;
            span(f, columns, rows, i0, i1, j0, j1);
            total += std::size_t(i1 - i0 + 1) * std::size_t(j1 - j0 + 1);
        }
        if (total <= kMaxEntries || (columns == 1.0 && rows == 1.0 && required)) break;
        if (columns == 1.0 && rows == 1.0) return grid;
        columns = std::max(1.0, std::ceil(columns / 2));
        rows = std::max(1.0, std::ceil(rows / 2));
    }

    const std::size_t cols = static_cast<std::size_t>(columns), rws = static_cast<std::size_t>(rows);
    std::vector<std::vector<const Footprint*>> lists(cols * rws);
    for (const Footprint& f : prints) {
        int i0, i1, j0, j1;
        span(f, columns, rows, i0, i1, j0, j1);
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) lists[std::size_t(j) * cols + std::size_t(i)].push_back(&f);
    }
    // The mean length of the list an entry is in: a few long lists among many short ones (boxes
    // one behind the other) weigh as much as the entries in them.
    double squares = 0.0;
    for (const auto& list : lists) squares += double(list.size()) * double(list.size());
    if (total > 0 && squares / double(total) > kMaxMeanList && !required) return grid;

    grid.origin = vec4(float(origin.x), float(origin.y), float(origin.z), 0.0f);
    grid.axis = vec4(float(axis.x), float(axis.y), float(axis.z), 0.0f);
    grid.across_u = vec4(float(u.x), float(u.y), float(u.z), 0.0f);
    grid.across_v = vec4(float(v.x), float(v.y), float(v.z), 0.0f);
    grid.window = vec4(float(wu0), float(wv0), float(columns / (wu1 - wu0)), float(rows / (wv1 - wv0)));
    grid.columns = static_cast<uint>(cols);
    grid.rows = static_cast<uint>(rws);
    grid.first_cell = static_cast<uint>(out.cells.size());
    grid.valid = 1;
    // Each cell's primitives nearest first (then by index, so the lists do not depend on the sort).
    for (auto& list : lists) {
        out.cells.push_back(static_cast<uint>(out.entries.size() / 2));
        std::sort(list.begin(), list.end(), [](const Footprint* a, const Footprint* b) {
            return a->near < b->near || (a->near == b->near && a->index < b->index);
        });
        for (const Footprint* f : list) {
            uint near_bits;
            std::memcpy(&near_bits, &f->near, sizeof near_bits);
            out.entries.push_back(f->index);
            out.entries.push_back(near_bits);
        }
    }
    out.cells.push_back(static_cast<uint>(out.entries.size() / 2));
    return grid;
}

DirectionGrids no_grids() {
    DirectionGrids out;
    out.grids.resize(DIRECTION_GRID_COUNT);
    return out;
}

void add_light_grids(std::span<const Light> lights, std::span<const Aabb> boxes, DirectionGrids& out, bool required) {
    for (std::size_t k = 0; k < lights.size() && DIRECTION_GRID_LIGHT + k < DIRECTION_GRID_COUNT; ++k) {
        const Light& l = lights[k];
        if (l.type != LIGHT_POINT && l.type != LIGHT_SPOT) continue;  // an area light's shadow rays end anywhere on it
        out.grids[DIRECTION_GRID_LIGHT + k] =
            direction_grid(dvec3(l.position.x, l.position.y, l.position.z), boxes, nullptr, out, 0.0, required);
    }
}

void add_view_grids(const EyeView& view, const Mirror* mirror, std::span<const Aabb> boxes, DirectionGrids& out, bool required) {
    out.grids[DIRECTION_GRID_EYE] = direction_grid(view.eye, boxes, &view, out, 0.0, required);
    if (!mirror) return;
    // A camera ray's reflection starts just off the plane (common.glsl's offset_origin: about
    // 2.3e-6 (|eye| + |point| + t) for a plane hit at t >= the eye's height h above it), so
    // its line passes that far from the mirror image: 2.3e-6 (1 + (|eye| + |point|) / h)
    // radians at most, here with a margin of 40. An eye on the plane sees no reflection in it.
    const double h = std::abs(glm::dot(view.eye - mirror->point, mirror->normal));
    if (!(h > 0.0)) return;
    auto reflect = [&](const dvec3& d) { return d - 2.0 * glm::dot(d, mirror->normal) * mirror->normal; };
    const EyeView image{view.eye - 2.0 * glm::dot(view.eye - mirror->point, mirror->normal) * mirror->normal,
                        reflect(view.forward), reflect(view.right), reflect(view.up)};
    const double slack = 1e-4 * (1.0 + (max_abs(view.eye) + max_abs(mirror->point)) / h);
    out.grids[DIRECTION_GRID_MIRROR] = direction_grid(image.eye, boxes, &image, out, slack, required);
}

}  // namespace lancer::gpu

#include "surface/closed_surface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/ext/vector_int3_sized.hpp>
#include <glm/geometric.hpp>

#include "core/error.hpp"

namespace lancer::surface {
namespace {

struct Segment {
    dvec3 from, to;
    bool matched = false;
};

// The boundary of each grid, counter-clockwise in (u, v): the side to its left is the patch's,
// seen with S_u x S_v toward the viewer.
std::vector<Segment> boundary(const std::vector<SampledPatch>& patches) {
    std::vector<Segment> segments;
    for (const SampledPatch& p : patches) {
        const int n = p.n;
        auto at = [&](int i, int j) { return p.points[std::size_t(i) * (n + 1) + j]; };
        for (int k = 0; k < n; ++k) {
            segments.push_back({at(k, 0), at(k + 1, 0)});          // v = start, u forward
            segments.push_back({at(n, k), at(n, k + 1)});          // u = end, v forward
            segments.push_back({at(n - k, n), at(n - k - 1, n)});  // v = end, u back
            segments.push_back({at(0, n - k), at(0, n - k - 1)});  // u = start, v back
        }
    }
    return segments;
}

std::string point(const dvec3& p) { return fmt::format("({:.4g}, {:.4g}, {:.4g})", p.x, p.y, p.z); }

}  // namespace

int outward_side(const std::vector<SampledPatch>& patches) {
    dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const SampledPatch& p : patches)
        for (const dvec3& q : p.points) lo = glm::min(lo, q), hi = glm::max(hi, q);
    const double size = glm::length(hi - lo);
    if (!(size > 0.0) || !std::isfinite(size)) throw UserError("it has no extent, so it encloses no solid");
    const double tolerance = 1e-7 * size;

    // Each boundary segment that is not a point must meet one running the other way: their
    // middles are then within the tolerance, so in neighbouring cells of a grid of twice its size.
    std::vector<Segment> segments = boundary(patches);
    std::erase_if(segments, [&](const Segment& s) { return glm::length(s.to - s.from) <= tolerance; });
    const double cell = 2.0 * tolerance;
    auto cell_of = [&](const Segment& s) { return glm::i64vec3(glm::floor((0.5 * (s.from + s.to) - lo) / cell)); };
    auto hash = [](const glm::i64vec3& c) {
        return std::hash<std::int64_t>()(c.x * 73856093 ^ c.y * 19349663 ^ c.z * 83492791);
    };
    std::unordered_map<glm::i64vec3, std::vector<std::size_t>, decltype(hash)> grid(segments.size(), hash);
    for (std::size_t i = 0; i < segments.size(); ++i) grid[cell_of(segments[i])].push_back(i);
    for (Segment& s : segments) {
        if (s.matched) continue;
        bool reversed = false, same_way = false;
        const glm::i64vec3 c = cell_of(s);
        for (int n = 0; n < 27 && !reversed; ++n) {
            const auto found = grid.find(c + glm::i64vec3(n % 3 - 1, n / 3 % 3 - 1, n / 9 - 1));
            if (found == grid.end()) continue;
            for (std::size_t k : found->second) {
                Segment& o = segments[k];
                if (o.matched || &o == &s) continue;
                if (glm::length(o.from - s.to) <= tolerance && glm::length(o.to - s.from) <= tolerance) {
                    o.matched = s.matched = reversed = true;
                    break;
                }
                same_way |= glm::length(o.from - s.from) <= tolerance && glm::length(o.to - s.to) <= tolerance;
            }
        }
        if (reversed) continue;
        if (same_way)
            throw UserError(fmt::format("two of its patches meet along the edge from {} to {} with opposite orientations "
                                        "(S_u x S_v points out of the solid on one side, in on the other), so it bounds no solid",
                                        point(s.from), point(s.to)));
        throw UserError(fmt::format("it is not closed: the edge of its samples from {} to {} meets no other edge "
                                    "(a closed surface's patches meet edge to edge, or an edge shrinks to a point)",
                                    point(s.from), point(s.to)));
    }

    // The signed volume of the grids' triangles, about the box's centre (the divergence theorem).
    const dvec3 centre = 0.5 * (lo + hi);
    double volume = 0.0;
    for (const SampledPatch& p : patches) {
        const int n = p.n;
        auto at = [&](int i, int j) { return p.points[std::size_t(i) * (n + 1) + j] - centre; };
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const dvec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
                volume += (glm::dot(a, glm::cross(b, c)) + glm::dot(a, glm::cross(c, d))) / 6.0;
            }
    }
    const dvec3 extent = hi - lo;
    if (!(std::abs(volume) > 1e-6 * std::max({extent.x * extent.y * extent.z, 1e-6 * size * size * size})))
        throw UserError(fmt::format("it encloses no volume (its samples' signed volume is {:.3g})", volume));
    return volume > 0.0 ? 1 : -1;
}

}  // namespace lancer::surface

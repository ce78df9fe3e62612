// POV-Ray's prism:
//   type = "prism"   sweep = "linear" | "conic"   spline = "linear" | "quadratic" | "cubic" | "bezier"
//   height1 = 0   height2 = 1   points = [[x, z], ...]   open = false
// POV-Ray's prism { linear_sweep|conic_sweep <spline> h1, h2, N, <x, z>, ... [open] }: sub-paths that close
// where a point repeats the sub-path's first (POV-Ray's rules per spline: a quadratic sub-path
// has one control point before it, a cubic one before and one after; a Bezier segment is 4
// points, and consecutive segments that share their end and start are one sub-path). Each piece
// becomes a 2-D Bezier segment exactly (scene/prism.hpp's make_prism builds the prism).
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scene/parse_surfaces.hpp"
#include "scene/prism.hpp"
#include "scene/shape_bounds.hpp"

namespace lancer {
namespace {

using PrismPoint = PointAt;

// POV-Ray's test of a repeated point (its EPSILON); the repeat is then taken as the very point.
bool prism_same_point(const glm::dvec2& a, const glm::dvec2& b) {
    return std::abs(a.x - b.x) < 1e-10 && std::abs(a.y - b.y) < 1e-10;
}

std::vector<PrismPoint> read_prism_points(TableReader& t) {
    return read_point_list(t, "points", "x", "z", "a prism needs points = [[x, z], ...] (its outline, as POV-Ray's prism's)");
}

PrismSegment prism_line_segment(const glm::dvec2& a, const glm::dvec2& b) {
    PrismSegment s;
    s.degree = 1;
    s.p[0] = a;
    s.p[1] = b;
    return s;
}

[[noreturn]] void prism_not_closed(const TableReader& t, const std::vector<PrismPoint>& p, std::size_t first, const char* rule) {
    throw SceneError(p[first].at, fmt::format("{} points[{}]: this sub-path does not close: {}", t.what(), first, rule));
}

// The sub-paths of POV-Ray's spline kinds as Bezier segments.
std::vector<PrismSegment> prism_segments(const TableReader& t, const std::vector<PrismPoint>& p, int spline) {
    std::vector<PrismSegment> out;
    const std::size_t n = p.size();
    // The sub-path's closing point: the first after `first` (from `from`) that repeats it.
    auto closing = [&](std::size_t first, std::size_t from) {
        for (std::size_t j = from; j < n; ++j)
            if (prism_same_point(p[j].p, p[first].p)) return j;
        return n;
    };
    if (spline == 0) {  // linear: the points, the first repeated at the end
        for (std::size_t first = 0; first < n;) {
            const std::size_t end = closing(first, first + 1);
            if (end == n) prism_not_closed(t, p, first, "no later point repeats it (POV-Ray closes a linear prism with a warning)");
            if (end < first + 3)
                throw SceneError(p[end].at, fmt::format("{} points[{}]: a sub-path needs at least 3 corners before it closes", t.what(), end));
            for (std::size_t i = first; i < end; ++i) out.push_back(prism_line_segment(p[i].p, i + 1 == end ? p[first].p : p[i + 1].p));
            first = end + 1;
        }
    } else if (spline == 1 || spline == 2) {  // quadratic, cubic: a control point before (and, cubic, after)
        const bool cubic = spline == 2;
        for (std::size_t control = 0; control < n;) {
            const std::size_t first = control + 1;
            if (first >= n)
                throw SceneError(p[control].at, fmt::format("{} points[{}]: a {} sub-path needs its first point after this control point",
                                                            t.what(), control, cubic ? "cubic" : "quadratic"));
            const std::size_t end = closing(first, first + 1);
            if (end == n) prism_not_closed(t, p, first, "no later point repeats it");
            if (end < first + 2)
                throw SceneError(p[end].at, fmt::format("{} points[{}]: a sub-path needs at least 2 points before it closes", t.what(), end));
            if (cubic && end + 1 >= n)
                throw SceneError(p[end].at, fmt::format("{} points[{}]: a cubic sub-path needs a control point after the point that closes it",
                                                        t.what(), end));
            for (std::size_t i = first; i < end; ++i) {
                // POV-Ray's piece from P[i] to P[i + 1], its neighbours P[i - 1] (and P[i + 2]).
                const glm::dvec2 a = p[i - 1].p, b = p[i].p, c = i + 1 == end ? p[first].p : p[i + 1].p;
                PrismSegment s;
                if (!cubic) {  // b + (c - a)/2 u + (a - 2b + c)/2 u^2
                    s.degree = 2;
                    s.p = {b, b + 0.25 * (c - a), c, c};
                } else {  // Catmull-Rom through b and c
                    const glm::dvec2 d = p[i + 2].p;
                    s.degree = 3;
                    s.p = {b, b + (c - a) / 6.0, c - (d - b) / 6.0, c};
                }
                out.push_back(s);
            }
            control = cubic ? end + 2 : end + 1;
        }
    } else {  // Bezier: 4 points a segment; one sub-path while a segment starts where the last ended
        if (n % 4 != 0)
            t.fail("points", fmt::format("a bezier_spline prism takes 4 points per segment, not {} points", n));
        std::size_t first = 0;
        for (std::size_t i = 0; i < n; i += 4) {
            PrismSegment s;
            s.degree = 3;
            s.p = {p[i].p, p[i + 1].p, p[i + 2].p, p[i + 3].p};
            if (i > first) s.p[0] = out.back().p[3];  // the same point as the last segment's end
            out.push_back(s);
            const bool last = i + 4 == n || !prism_same_point(p[i + 4].p, p[i + 3].p);
            if (!last) continue;
            if (!prism_same_point(p[i + 3].p, p[first].p))
                prism_not_closed(t, p, first, fmt::format("its last segment ends at points[{}], not where it starts", i + 3).c_str());
            out.back().p[3] = out[out.size() - 1 - (i - first) / 4].p[0];
            first = i + 4;
        }
    }
    return out;
}

}  // namespace

Shape read_prism(TableReader& t, const glm::dmat4&) {
    const bool conic = one_of(t, "sweep", "sweep", {"linear", "conic"}, "linear") == 1;
    const auto spline = static_cast<int>(one_of(t, "spline", "spline", {"linear", "quadratic", "cubic", "bezier"}, "linear"));
    const double height1 = t.number("height1", 0.0), height2 = t.number("height2", 1.0);
    if (height1 == height2) t.fail("height2", fmt::format("{}: height1 and height2 are both {:g}: the prism would be flat", t.what(), height1));
    if (conic && height1 * height2 < 0.0)
        t.fail("height2", fmt::format("{}: a conic sweep's heights {:g} and {:g} lie on both sides of its apex (y = 0): POV-Ray's "
                                      "conic_sweep scales the outline by y, so each must be at or beyond 0 on one side",
                                      t.what(), height1, height2));
    const bool open = t.boolean("open", false);
    const std::vector<PrismPoint> points = read_prism_points(t);
    static constexpr std::size_t kLeast[4] = {3, 5, 6, 4};
    static constexpr const char* kNames[4] = {"linear", "quadratic", "cubic", "bezier"};
    if (points.size() < kLeast[spline])
        t.fail("points", fmt::format("a {}_spline prism needs at least {} points, not {} (as POV-Ray's)", kNames[spline], kLeast[spline],
                                     points.size()));
    Prism o = make_prism(prism_segments(t, points, spline), height1, height2, open, conic);
    const std::optional<Aabb> box = shape_bounds(o);
    check_world_extent(t, "points", box->lo, box->hi);
    return o;
}

}  // namespace lancer

// POV-Ray's lathe:
//   type = "lathe"   spline = "linear"   points = [[r0, y0], [r1, y1], ...]
// POV-Ray's lathe { [linear_spline | quadratic_spline | cubic_spline | bezier_spline] n, <r0, y0>, ... }
// (linear_spline its default), each spline piece turned into the Bezier segment it is:
//   linear:    n >= 2, segment i from point i to i + 1;
//   quadratic: n >= 3, segment i from point i + 1 to i + 2, its start's tangent from points i and
//              i + 2 (point 0 gives only the first tangent);
//   cubic:     n >= 4, segment i from point i + 1 to i + 2, Catmull-Rom tangents from the points
//              either side (points 0 and n - 1 give only the end tangents);
//   bezier:    n a multiple of 4, each 4 points one cubic Bezier segment.
// POV-Ray 3.8 refuses negative radii at the points the curve passes through (and, for a linear
// spline, everywhere); lancer does too, and also a curve whose radius dips below 0 between them
// (a negative control radius may pull it there), whose surface would be the mirrored curve.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scene/bezier_curve.hpp"
#include "scene/lathe_crossing.hpp"
#include "scene/limits.hpp"
#include "scene/parse_surfaces.hpp"

namespace lancer {
namespace {

struct LathePoint {
    double r, y;
    SourceLocation at;
};

enum class LatheSpline { Linear, Quadratic, Cubic, Bezier };

std::vector<LathePoint> read_lathe_points(TableReader& t) {
    std::vector<LathePoint> points;
    for (const PointAt& q : read_point_list(t, "points", "radius", "height", "a lathe needs points = [[radius, height], ...] (as POV-Ray's lathe)"))
        points.push_back({q.p.x, q.p.y, q.at});
    return points;
}

// The smallest radius of a segment's curve over s in [0, 1]: at its ends or where r turns.
double lathe_least_radius(const LatheSegment& g, int n) {
    double least = std::min(g.r[0], g.r[n]);
    for (double s : bezier_turning_points(g.r, n)) least = std::min(least, bezier_at(g.r, n, s));
    return least;
}

// Twice the signed area a segment sweeps about the origin of the (r, y) plane, the integral of
// r y' - y r' over s (a polynomial of degree 2n - 1 <= 5: 3-point Gauss-Legendre is exact).
double lathe_twice_area(const LatheSegment& g, int n) {
    static constexpr double kNode[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
    static constexpr double kWeight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    std::array<double, 4> dr{}, dy{};
    for (int i = 0; i < n; ++i) {
        dr[i] = n * (g.r[i + 1] - g.r[i]);
        dy[i] = n * (g.y[i + 1] - g.y[i]);
    }
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double s = 0.5 * (kNode[k] + 1.0);
        const double r = bezier_at(g.r, n, s), y = bezier_at(g.y, n, s);
        const double rp = bezier_at(dr, n - 1, s), yp = bezier_at(dy, n - 1, s);
        sum += 0.5 * kWeight[k] * (r * yp - y * rp);
    }
    return sum;
}

}  // namespace

Shape read_lathe(TableReader& t, const glm::dmat4&) {
    const auto spline = static_cast<LatheSpline>(
        one_of(t, "spline", "lathe spline", {"linear", "quadratic", "cubic", "bezier"}, "linear"));
    const std::vector<LathePoint> p = read_lathe_points(t);
    const std::size_t n = p.size();
    static constexpr const char* kName[] = {"linear", "quadratic", "cubic", "bezier"};
    const auto name = kName[static_cast<int>(spline)];
    const std::size_t least = spline == LatheSpline::Linear ? 2 : spline == LatheSpline::Quadratic ? 3 : 4;
    if (n < least)
        t.fail("points", fmt::format("a lathe with a {} spline needs at least {} points, not {}{}", name, least, n,
                                     spline == LatheSpline::Quadratic ? ": the first gives only the first segment's tangent"
                                     : spline == LatheSpline::Cubic   ? ": the first and last give only the end tangents"
                                     : spline == LatheSpline::Bezier  ? ": 4 control points per segment"
                                                                      : ""));
    if (spline == LatheSpline::Bezier && n % 4 != 0)
        t.fail("points", fmt::format("a lathe with a bezier spline takes 4 points per segment, not {} points (a multiple of "
                                     "4, as POV-Ray's)",
                                     n));
    // The points the curve passes through (POV-Ray refuses negative radii there).
    for (std::size_t i = 0; i < n; ++i) {
        const bool on_curve = spline == LatheSpline::Linear      ? true
                              : spline == LatheSpline::Quadratic ? i > 0
                              : spline == LatheSpline::Cubic     ? i > 0 && i + 1 < n
                                                                 : (i % 4 == 0 || i % 4 == 3);
        if (on_curve && p[i].r < 0.0)
            throw SceneError(p[i].at, fmt::format("{} points[{}]: a radius must not be negative, not {:g} (the curve "
                                                  "passes through this point)",
                                                  t.what(), i, p[i].r));
    }

    Lathe o;
    o.degree = spline == LatheSpline::Linear ? 1 : spline == LatheSpline::Quadratic ? 2 : 3;
    // Each segment as Bezier control points, and the index of the first point it reads.
    std::vector<std::size_t> first_point;
    auto add = [&](std::size_t first, std::array<double, 4> r, std::array<double, 4> y) {
        LatheSegment g;
        g.r = r;
        g.y = y;
        first_point.push_back(first);
        o.segments.push_back(g);
    };
    if (spline == LatheSpline::Linear) {
        for (std::size_t i = 0; i + 1 < n; ++i) add(i, {p[i].r, p[i + 1].r, 0, 0}, {p[i].y, p[i + 1].y, 0, 0});
    } else if (spline == LatheSpline::Quadratic) {
        // POV-Ray's piece p1 + (p2 - p0)/2 s + (p0/2 - p1 + p2/2) s^2: control points p1, p1 + (p2 - p0)/4, p2.
        for (std::size_t i = 0; i + 2 < n; ++i)
            add(i, {p[i + 1].r, p[i + 1].r + 0.25 * (p[i + 2].r - p[i].r), p[i + 2].r, 0},
                {p[i + 1].y, p[i + 1].y + 0.25 * (p[i + 2].y - p[i].y), p[i + 2].y, 0});
    } else if (spline == LatheSpline::Cubic) {
        // Catmull-Rom from p1 to p2, tangents (p2 - p0)/2 and (p3 - p1)/2: control points p1,
        // p1 + (p2 - p0)/6, p2 - (p3 - p1)/6, p2.
        for (std::size_t i = 0; i + 3 < n; ++i)
            add(i,
                {p[i + 1].r, p[i + 1].r + (p[i + 2].r - p[i].r) / 6.0, p[i + 2].r - (p[i + 3].r - p[i + 1].r) / 6.0,
                 p[i + 2].r},
                {p[i + 1].y, p[i + 1].y + (p[i + 2].y - p[i].y) / 6.0, p[i + 2].y - (p[i + 3].y - p[i + 1].y) / 6.0,
                 p[i + 2].y});
    } else {
        for (std::size_t i = 0; i + 3 < n; i += 4)
            add(i, {p[i].r, p[i + 1].r, p[i + 2].r, p[i + 3].r}, {p[i].y, p[i + 1].y, p[i + 2].y, p[i + 3].y});
    }

    const int deg = o.degree;
    o.y_lo = INFINITY;
    o.y_hi = -INFINITY;
    for (std::size_t k = 0; k < o.segments.size(); ++k) {
        LatheSegment& g = o.segments[k];
        const double lowest = lathe_least_radius(g, deg);
        double scale = 0.0;
        for (int i = 0; i <= deg; ++i) scale = std::max({scale, std::abs(g.r[i]), std::abs(g.y[i])});
        if (lowest < -1e-12 * scale)
            throw SceneError(p[first_point[k]].at,
                             fmt::format("{} points[{}]: the curve's segment {} from this point dips below the axis (to radius "
                                         "{:.6g}): its surface would be the mirrored curve; move its control points to "
                                         "radii that keep it at or beyond 0",
                                         t.what(), first_point[k], k, lowest));
        g.r_max = 0.0;
        g.y_lo = g.y[0];
        g.y_hi = g.y[0];
        for (int i = 0; i <= deg; ++i) {
            g.r_max = std::max(g.r_max, std::abs(g.r[i]));
            g.y_lo = std::min(g.y_lo, g.y[i]);
            g.y_hi = std::max(g.y_hi, g.y[i]);
        }
        o.r_max = std::max(o.r_max, g.r_max);
        o.y_lo = std::min(o.y_lo, g.y_lo);
        o.y_hi = std::max(o.y_hi, g.y_hi);
    }
    if (!(o.r_max > 0.0)) t.fail("points", t.what() + ": every radius is 0: the lathe would be a line");

    // Closed: the pieces meet end to end, and the curve ends where it starts or on the axis at both ends.
    bool joined = true;
    for (std::size_t k = 0; k + 1 < o.segments.size(); ++k) {
        const LatheSegment &a = o.segments[k], &b = o.segments[k + 1];
        joined = joined && a.r[deg] == b.r[0] && a.y[deg] == b.y[0];
    }
    const LatheSegment &head = o.segments.front(), &tail = o.segments.back();
    const double r0 = head.r[0], y0 = head.y[0], r1 = tail.r[deg], y1 = tail.y[deg];
    o.closed = joined && ((r0 == r1 && y0 == y1) || (r0 == 0.0 && r1 == 0.0));

    // Which side is out: the curve's turning, by its signed area (closed by the chord from its
    // end back to its start where it is open: it is 0 along the axis). Counterclockwise in (r, y),
    // the outward normal is (y', -r').
    double twice_area = r1 * y0 - y1 * r0;
    for (const LatheSegment& g : o.segments) twice_area += lathe_twice_area(g, deg);
    double size = std::max({o.r_max, std::abs(o.y_lo), std::abs(o.y_hi)});
    if (o.closed && !(std::abs(twice_area) > 1e-12 * size * size))
        t.fail("points", t.what() + ": the closed curve encloses no area: the lathe would have no inside");
    for (LatheSegment& g : o.segments) g.side = twice_area >= 0.0 ? 1 : -1;

    // One side for the whole curve is right only where it does not meet itself: on a curve that
    // crosses itself the loops turning against the whole face inward, and its inside would be
    // ambiguous. POV-Ray draws it; lancer refuses it, at the later segment's first point on the curve.
    if (const std::optional<LatheSelfCrossing> crossing = find_lathe_crossing(o)) {
        if (crossing->crowded > 0.0)
            t.fail("points", fmt::format("{}: {:.3g} pairs of the curve's pieces overlap, more than the {:.3g} lancer checks "
                                         "for the curve crossing itself; use fewer pieces, or a linear spline (checked "
                                         "exactly however many)",
                                         t.what(), crossing->crowded, limits::kMaxLatheCrossingPairs));
        const auto on_curve = [&](std::size_t k) {
            return first_point[k] + (spline == LatheSpline::Quadratic || spline == LatheSpline::Cubic ? 1 : 0);
        };
        const std::size_t at = on_curve(crossing->second);
        throw SceneError(p[at].at,
                         fmt::format("{} points[{}]: the lathe's curve crosses itself (segment {} meets segment {}, which "
                                     "starts at this point, near r={:.6g}, y={:.6g}): its inside and its normals would be "
                                     "ambiguous; POV-Ray would draw it, lancer refuses it; keep the curve simple (its "
                                     "pieces meet only end to end)",
                                     t.what(), at, crossing->first, crossing->second, crossing->near.x, crossing->near.y));
    }

    check_world_extent(t, "points", dvec3(-o.r_max, o.y_lo, -o.r_max), dvec3(o.r_max, o.y_hi, o.r_max));
    return o;
}

}  // namespace lancer

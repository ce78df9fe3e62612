// POV-Ray's surface of revolution:
//   type = "sor"   points = [[r0, y0], [r1, y1], ...]   open = false
// POV-Ray's sor { n, <r0, y0>, ... [open] }: at least 4 points in increasing height; the surface
// passes through points 1 .. n-2, its radius squared a cubic in y on each segment between them
// (POV-Ray's spline: the squared radii at both ends, and slopes from the neighbours).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scene/parse_surfaces.hpp"

namespace lancer {
namespace {

struct SorPoint {
    double r, y;
    SourceLocation at;
};

std::vector<SorPoint> read_points(TableReader& t) {
    const std::vector<PointAt> list =
        read_point_list(t, "points", "radius", "height", "a sor needs points = [[radius, height], ...] (at least 4, as POV-Ray's sor)");
    std::vector<SorPoint> points;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const double r = list[i].p.x, y = list[i].p.y;
        const SourceLocation& at = list[i].at;
        const std::string what = fmt::format("{} points[{}]", t.what(), i);
        if (!(r >= 0.0)) throw SceneError(at, fmt::format("{}: a radius must not be negative, not {:g}", what, r));
        if (!points.empty() && !(y > points.back().y))
            throw SceneError(at, fmt::format("{}: heights must increase from point to point ({:g} follows {:g}), as "
                                             "POV-Ray's sor's",
                                             what, y, points.back().y));
        points.push_back({r, y, at});
    }
    if (points.size() < 4)
        t.fail("points", fmt::format("a sor needs at least 4 points, not {}: the first and last give the slopes at the "
                                     "ends of the curve through the others",
                                     points.size()));
    return points;
}

// The cubic about the segment's bottom through (0, k0) and (h, k1) with slopes s0 and s1: Hermite.
SorSegment segment(double y0, double y1, double k0, double k1, double s0, double s1) {
    SorSegment g;
    g.y0 = y0;
    g.y1 = y1;
    const double h = y1 - y0;
    const double e = k1 - k0 - s0 * h, f = s1 - s0;
    g.d = k0;
    g.c = s0;
    g.a = (f - 2.0 * e / h) / (h * h);
    g.b = e / (h * h) - g.a * h;
    // The largest radius: at the ends, or where r^2's derivative 3a u^2 + 2b u + c vanishes.
    auto r2 = [&](double u) { return ((g.a * u + g.b) * u + g.c) * u + g.d; };
    double most = std::max(k0, k1);
    const double qa = 3.0 * g.a, qb = 2.0 * g.b, qc = g.c;
    if (qa != 0.0) {
        const double disc = qb * qb - 4.0 * qa * qc;
        if (disc >= 0.0)
            for (double sign : {-1.0, 1.0}) {
                const double u = (-qb + sign * std::sqrt(disc)) / (2.0 * qa);
                if (u > 0.0 && u < h) most = std::max(most, r2(u));
            }
    } else if (qb != 0.0) {
        const double u = -qc / qb;
        if (u > 0.0 && u < h) most = std::max(most, r2(u));
    }
    g.r_max = std::sqrt(std::max(most, 0.0)) * (1.0 + 1e-9);
    return g;
}

}  // namespace

Shape read_sor(TableReader& t, const glm::dmat4&) {
    const std::vector<SorPoint> p = read_points(t);
    Sor o;
    o.open = t.boolean("open", false);
    // The slope of r^2 at point j, from its neighbours: 2 r_j (r_{j+1} - r_{j-1}) / (y_{j+1} - y_{j-1}).
    auto slope = [&](std::size_t j) { return 2.0 * p[j].r * (p[j + 1].r - p[j - 1].r) / (p[j + 1].y - p[j - 1].y); };
    for (std::size_t i = 1; i + 2 < p.size(); ++i)
        o.segments.push_back(segment(p[i].y, p[i + 1].y, p[i].r * p[i].r, p[i + 1].r * p[i + 1].r, slope(i), slope(i + 1)));
    o.base_r2 = p[1].r * p[1].r;
    o.cap_r2 = p[p.size() - 2].r * p[p.size() - 2].r;
    o.r_max = 0.0;
    for (const SorSegment& g : o.segments) o.r_max = std::max(o.r_max, g.r_max);
    if (!(o.r_max > 0.0)) t.fail("points", t.what() + ": every radius is 0: the sor would be a line");
    check_world_extent(t, "points", dvec3(-o.r_max, o.segments.front().y0, -o.r_max),
                       dvec3(o.r_max, o.segments.back().y1, o.r_max));
    return o;
}

}  // namespace lancer

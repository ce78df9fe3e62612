// Ray/surface of revolution (POV-Ray's sor) for the CPU reference, in double precision, written
// apart from its GLSL.
//
// In the sor's own coordinates (y along the axis) the curve is f(p) = x^2 + z^2 - r^2(y) = 0,
// r^2 a cubic on each segment (its own coefficients about the segment's bottom y0), closed by the
// base disc (y = bottom) and the cap disc (y = top) unless open; f < 0 inside. Along the ray
// c + s d, |d| = 1 (c its point nearest the origin), the slabs [y0, y1] cut the line into
// stretches that meet end to end (the boundary between two segments is the same s from both),
// each trimmed to the segment's bounding cylinder (widened by 1e-9 of the sor's size). Along a
// stretch f is a cubic g(tau), tau in [-1, 1], whose roots are isolated by Bernstein subdivision
// (cpu/shapes/bernstein_roots.hpp: a quartic whose leading coefficient is 0; a piece is dropped
// only on a proof that g keeps one sign over it), each found by bisection on f evaluated directly.
// A touching point, or a run where g is 0 to rounding (a line along a cylinder's wall or a cone's
// side, a stretch of a few ulps ending on the surface), is one root, not halved into 1e-12
// pieces that would each be one; a root on the boundary between two stretches, found from both,
// is one. The slabs are not widened: a root on a boundary (a rim, or where two segments meet) is
// found at its stretch's end, and widened slabs would overlap and find roots of a segment's cubic
// beyond its heights. Where r^2 < 0, f > 0: no surface there. A horizontal line belongs to the
// one segment with y0 <= y < y1 (the top's to the last), so that the curve at a boundary height is
// searched once; one in the base's or the cap's plane meets the curve at the rim (a hit, as a
// touching point is) while inside() holds nowhere along it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "cpu/shapes/bernstein_roots.hpp"
#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

// The ray with a unit direction, about its point nearest the origin: t = (tc + s) / length.
struct SorLine {
    dvec3 c, d;
    double tc, length;
};

std::optional<SorLine> sor_line(const Ray& ray) {
    const double length = glm::length(ray.dir);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    SorLine line;
    line.d = ray.dir / length;
    line.tc = -glm::dot(ray.origin, line.d);
    line.c = ray.origin + line.tc * line.d;
    line.length = length;
    return line;
}

// r^2 on the segment at u = y - y0, and its derivative.
double sor_r2(const SorSegment& s, double u) { return ((s.a * u + s.b) * u + s.c) * u + s.d; }
double sor_r2_slope(const SorSegment& s, double u) { return (3.0 * s.a * u + 2.0 * s.b) * u + s.c; }

// f at p, evaluated directly with the segment's r^2 (accurate near the surface).
double sor_f(const SorSegment& s, const dvec3& p) { return (p.x * p.x + p.z * p.z) - sor_r2(s, p.y - s.y0); }

// The curve's outward unit normal at p (grad f = (2x, -dr^2/dy, 2z)); where it vanishes (a
// touching point on the axis where r^2 has a double root), facing the ray.
dvec3 sor_curve_normal(const SorSegment& s, const dvec3& p, const dvec3& d) {
    const dvec3 g(2.0 * p.x, -sor_r2_slope(s, p.y - s.y0), 2.0 * p.z);
    const double length = glm::length(g);
    return length > 0.0 ? g / length : -d;
}

double sor_bottom(const Sor& o) { return o.segments.front().y0; }
double sor_top(const Sor& o) { return o.segments.back().y1; }

// The size the bounding cylinders are widened by a fraction of.
double sor_scale(const Sor& o) { return std::max({o.r_max, std::abs(sor_bottom(o)), std::abs(sor_top(o))}); }

constexpr double kSorMargin = 1e-9;  // of the sor's size: the curve touches its bounding cylinders

struct SorRoot {
    double t;
    dvec3 normal;
};

// The curve's roots along the line with t in (t_min, t_max), nearest first (only the nearest, or
// all).
std::vector<SorRoot> sor_curve_roots(const Sor& o, const SorLine& line, double t_min, double t_max, bool nearest_only) {
    std::vector<SorRoot> roots;
    const std::size_t n = o.segments.size();
    const dvec3& c = line.c;
    const dvec3& d = line.d;
    const double s_min = t_min * line.length - line.tc, s_max = t_max * line.length - line.tc;
    const double widen = kSorMargin * sor_scale(o);
    const double across = d.x * d.x + d.z * d.z;  // the direction's part across the axis, squared
    double run_end = 0.0, run_half = 0.0;  // where the last root's piece ends, and its stretch's half width
    for (std::size_t i = 0; i < n; ++i) {
        // The segments in the order the ray meets them.
        const std::size_t k = d.y < 0.0 ? n - 1 - i : i;
        const SorSegment& seg = o.segments[k];
        double lo = s_min, hi = s_max;
        if (d.y != 0.0) {
            double a = (seg.y0 - c.y) / d.y, b = (seg.y1 - c.y) / d.y;
            if (a > b) std::swap(a, b);
            lo = std::max(lo, a);
            hi = std::min(hi, b);
        } else if (!(seg.y0 <= c.y && (c.y < seg.y1 || (k + 1 == n && c.y <= seg.y1)))) {
            continue;
        }
        const double R = std::max(seg.r_max, 0.0) + widen;
        if (across > 0.0) {
            const double middle = -(c.x * d.x + c.z * d.z) / across;
            const double nx = c.x + middle * d.x, nz = c.z + middle * d.z;
            const double reach2 = (R * R - (nx * nx + nz * nz)) / across;
            if (!(reach2 >= 0.0)) continue;
            const double reach = std::sqrt(reach2);
            lo = std::max(lo, middle - reach);
            hi = std::min(hi, middle + reach);
        } else if (c.x * c.x + c.z * c.z > R * R) {
            continue;
        }
        if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi)) continue;

        // g(tau) = f(P + half tau d), P the stretch's middle: x, z and u = y - y0 are linear in tau.
        const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
        const dvec3 P = c + mid * d;
        const double X0 = P.x, X1 = half * d.x, Z0 = P.z, Z1 = half * d.z;
        const double U0 = P.y - seg.y0, U1 = half * d.y;
        const double A = std::abs(seg.a), B = std::abs(seg.b), C = std::abs(seg.c), aU0 = std::abs(U0), aU1 = std::abs(U1);
        // f = rho^2 - r^2: power coefficients, and the sums of their terms' magnitudes.
        bernstein::Quartic p{}, m{};
        p[0] = sor_f(seg, P);
        m[0] = X0 * X0 + Z0 * Z0 + ((A * aU0 + B) * aU0 + C) * aU0 + std::abs(seg.d);
        p[1] = 2.0 * (X0 * X1 + Z0 * Z1) - sor_r2_slope(seg, U0) * U1;
        m[1] = 2.0 * (std::abs(X0 * X1) + std::abs(Z0 * Z1)) + ((3.0 * A * aU0 + 2.0 * B) * aU0 + C) * aU1;
        p[2] = X1 * X1 + Z1 * Z1 - (3.0 * seg.a * U0 + seg.b) * U1 * U1;
        m[2] = X1 * X1 + Z1 * Z1 + (3.0 * A * aU0 + B) * U1 * U1;
        p[3] = -seg.a * U1 * U1 * U1;
        m[3] = std::abs(p[3]);
        const bernstein::Form bern = bernstein::from_power(p, m);
        // A few dozen roundings of the magnitudes per coefficient (the line, x, z and u, r^2's
        // re-expansion, two changes of basis): 256 is generous.
        const double error = 256.0 * bernstein::kEpsilon * bern.magnitude;

        auto at = [&](double tau) { return P + (half * tau) * d; };
        auto sigma = [&](double tau) { return mid + half * tau; };
        auto value = [&](double tau) { return sor_f(seg, at(tau)); };
        auto accept = [&](double tau, double from, double to) {
            const double t = (line.tc + sigma(tau)) / line.length;
            if (!(t > t_min && t < t_max)) return false;
            // Pieces told apart by no more than rounding are one root: a touching point's run of
            // pieces, and a root on the boundary between two stretches, found from both sides.
            const double slack = bernstein::kTouchingWidth * (run_half + half);
            if (!roots.empty() && sigma(from) <= run_end + slack) {
                run_end = std::max(run_end, sigma(to));
                run_half = half;
                return nearest_only;
            }
            roots.push_back({t, sor_curve_normal(seg, at(tau), d)});
            run_end = sigma(to);
            run_half = half;
            return nearest_only;
        };
        if (bernstein::isolate(bern.c, -1.0, 1.0, error, value, accept, true)) break;
    }
    return roots;
}

// The discs' crossings with t in (t_min, t_max) (none where open, or where a disc's radius is 0:
// the curve closes the sor there), appended to `hits`.
void sor_disc_hits(const Sor& o, const SorLine& line, double t_min, double t_max, std::vector<SorRoot>& hits) {
    if (o.open || line.d.y == 0.0) return;
    auto disc = [&](double y, double r2, double ny) {
        if (!(r2 > 0.0)) return;
        const double s = (y - line.c.y) / line.d.y;
        const double t = (line.tc + s) / line.length;
        if (!(t > t_min && t < t_max)) return;
        const double x = line.c.x + s * line.d.x, z = line.c.z + s * line.d.z;
        if (x * x + z * z <= r2) hits.push_back({t, dvec3(0.0, ny, 0.0)});
    };
    disc(sor_bottom(o), o.base_r2, -1.0);
    disc(sor_top(o), o.cap_r2, 1.0);
}

}  // namespace

std::optional<SurfaceHit> intersect(const Sor& o, const Ray& ray, double t_min, double t_max) {
    const std::optional<SorLine> line = sor_line(ray);
    if (!line || o.segments.empty()) return std::nullopt;
    std::vector<SorRoot> hits;
    sor_disc_hits(o, *line, t_min, t_max, hits);
    // The curve only before the nearer disc hit (a tie goes to the disc).
    double limit = t_max;
    for (const SorRoot& h : hits) limit = std::min(limit, h.t);
    const std::vector<SorRoot> curve = sor_curve_roots(o, *line, t_min, limit, true);
    hits.insert(hits.end(), curve.begin(), curve.end());
    if (hits.empty()) return std::nullopt;
    const SorRoot& nearest = *std::min_element(hits.begin(), hits.end(), [](const SorRoot& a, const SorRoot& b) { return a.t < b.t; });
    return SurfaceHit{nearest.t, nearest.normal};
}

std::vector<double> roots_on_line(const Sor& o, const Ray& ray) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const std::optional<SorLine> line = sor_line(ray);
    if (!line || o.segments.empty()) return {};
    std::vector<SorRoot> hits = sor_curve_roots(o, *line, -kInfinity, kInfinity, false);
    sor_disc_hits(o, *line, -kInfinity, kInfinity, hits);
    std::vector<double> roots;
    for (const SorRoot& h : hits) roots.push_back(h.t);
    std::sort(roots.begin(), roots.end());
    return roots;
}

// Between the base and the cap (strictly) and f < 0, with the segment that holds the height.
bool inside(const Sor& o, const dvec3& p) {
    if (o.segments.empty() || !(p.y > sor_bottom(o) && p.y < sor_top(o))) return false;
    const auto seg = std::lower_bound(o.segments.begin(), o.segments.end(), p.y, [](const SorSegment& s, double y) { return s.y1 < y; });
    const SorSegment& s = seg == o.segments.end() ? o.segments.back() : *seg;
    return sor_f(s, p) < 0.0;
}

// u the angle about y from +x toward +z over 2 pi in [0, 1), v the height from the bottom (0) to
// the top (1), clamped.
glm::dvec2 texture_uv(const Sor& o, const dvec3& p) {
    double angle = (p.x == 0.0 && p.z == 0.0) ? 0.0 : std::atan2(p.z, p.x);
    if (angle < 0.0) angle += 2.0 * M_PI;
    double u = angle / (2.0 * M_PI);
    if (u >= 1.0) u = 0.0;
    if (o.segments.empty()) return {u, 0.0};
    const double bottom = sor_bottom(o), height = sor_top(o) - bottom;
    const double v = height > 0.0 ? std::clamp((p.y - bottom) / height, 0.0, 1.0) : 0.0;
    return {u, v};
}

}  // namespace lancer::cpu

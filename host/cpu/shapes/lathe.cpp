// Ray/lathe (POV-Ray's lathe) for the CPU reference, in double precision, written apart from its
// GLSL.
//
// In the lathe's own coordinates each segment is a Bezier curve (r(s), y(s)) of degree n (1, 2
// or 3), s in [0, 1], turned about the y axis. Along the ray c + sigma d, |d| = 1 (c its point
// nearest the origin), a point of the surface has y(s) = c.y + sigma d.y and x^2 + z^2 = r(s)^2;
// times d.y^2, with d.y x = d.y c.x + (y(s) - c.y) d.x (and z alike),
//     F(s) = (d.y c.x + (y(s) - c.y) d.x)^2 + (d.y c.z + (y(s) - c.y) d.z)^2 - (d.y r(s))^2 = 0,
// a polynomial of degree 2n in s (POV-Ray's own equation). Its Bernstein coefficients over
// [0, 1] come straight from the control points (the two factors' control values, multiplied as
// Bernstein polynomials are), and its roots are isolated by Bernstein subdivision
// (cpu/shapes/bernstein_roots.hpp: a piece is dropped only on a proof that F keeps one sign
// over it), each found by bisection on F evaluated directly from the curve.
//
// For a ray more along the axis than across it, F is taken over the whole segment and sigma is
// (y(s) - c.y) / d.y. Else F's roots come in pairs about the ray's point nearest the axis (it
// nears the axis and leaves it at almost one height), as close as the ray is level: so the ray's
// stretch through the segment's band is cut there, and each half taken over the pieces of s where
// y(s) is monotone and lies within the half's heights (F's Bernstein form built over each piece
// from the piece's own control points, so that it is resolved however narrow the piece); sigma is
// then where the circle of radius r(s) crosses the line on that half's side (POV-Ray's special case
// of the level ray, made general). Roots of neighbouring segments at their shared point, and of
// neighbouring pieces, are merged when within 1e-9 of the lathe's size.
//
// inside: POV-Ray's even-odd rule: the half-line from the point away from the axis at its height
// crosses the curve where y(s) = p.y and r(s) > rho, counted per segment by isolating the roots
// of the Bezier y(s) - p.y; a root told only within rounding counts where y - p.y changes sign
// (> 0 against <= 0) across its piece, so that a crossing at a point shared by two segments
// counts once, and a touching point twice or not at all.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "cpu/shapes/bernstein_roots.hpp"
#include "cpu/shapes/shapes.hpp"
#include "scene/bezier_curve.hpp"

namespace lancer::cpu {
namespace {

struct LatheLine {
    dvec3 c, d;
    double tc, length;
};

std::optional<LatheLine> lathe_line(const Ray& ray) {
    const double length = glm::length(ray.dir);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    LatheLine line;
    line.d = ray.dir / length;
    line.tc = -glm::dot(ray.origin, line.d);
    line.c = ray.origin + line.tc * line.d;
    line.length = length;
    return line;
}

double lathe_size(const Lathe& o) { return std::max({o.r_max, std::abs(o.y_lo), std::abs(o.y_hi)}); }

// The outward unit normal at the curve's parameter s (the segment's side of (y', -r'), turned
// about the axis to the point p); on the axis, along it. Where the curve's tangent vanishes (a
// repeated control point at an end), its chord's.
dvec3 lathe_normal(const Lathe& o, const LatheSegment& g, double s, const dvec3& p, const dvec3& d) {
    const int n = o.degree;
    double rp = bezier_slope(g.r, n, s), yp = bezier_slope(g.y, n, s);
    if (rp == 0.0 && yp == 0.0) {
        rp = g.r[n] - g.r[0];
        yp = g.y[n] - g.y[0];
    }
    const double nr = g.side * yp, ny = -g.side * rp;
    const double rho = std::hypot(p.x, p.z);
    const dvec3 v = rho > 0.0 ? dvec3(nr * p.x / rho, ny, nr * p.z / rho) : dvec3(0.0, ny, 0.0);
    const double length = glm::length(v);
    return length > 0.0 ? v / length : -d;
}

struct LatheRoot {
    double sigma;
    dvec3 normal;
    glm::dvec2 uv;  // (segment, s)
};

// The piece [s0, s1] of a segment's curve (split twice): control values of degree n.
std::array<double, 4> lathe_piece(const std::array<double, 4>& b, int n, double s0, double s1) {
    std::array<double, 4> left{}, right = b;
    if (s0 > 0.0) bezier_split(b, n, s0, left, right);
    if (!(s1 < 1.0)) return right;
    std::array<double, 4> piece{}, rest{};
    bezier_split(right, n, s0 > 0.0 ? (s1 - s0) / (1.0 - s0) : s1, piece, rest);
    return piece;
}

// Where the segment's y(s) turns (y'(s) = 0 in (0, 1)), with 0 and 1, in order.
std::vector<double> lathe_monotone_ends(const std::array<double, 4>& y, int n) {
    std::vector<double> ends{0.0};
    for (double s : bezier_turning_points(y, n)) ends.push_back(s);
    ends.push_back(1.0);
    return ends;
}

// The s in [a, b] where y(s) = Y, y monotone there, y(a) - Y of sign `a_above` (bisection).
double lathe_height_at(const std::array<double, 4>& y, int n, double Y, double a, double b, bool a_above) {
    for (int i = 0; i < 200; ++i) {
        const double m = 0.5 * (a + b);
        if (!(m > a && m < b)) break;
        if ((bezier_at(y, n, m) - Y > 0.0) == a_above) a = m; else b = m;
    }
    return 0.5 * (a + b);
}

// What a segment's roots need to know of the ray.
struct LatheAcross {
    double s_min, s_max;  // the sigma range wanted
    double middle;        // sigma nearest the axis
    double rho0_2;        // the line's distance from the axis there, squared
    double across;        // d.x^2 + d.z^2
};

// The roots of F over the piece [s0, s1] of segment k (sigma from y(s) where side is 0, else
// from the circle of radius r(s) on that side of `middle`), appended to `out`.
template <int n>
void lathe_piece_roots(const Lathe& o, std::size_t k, const LatheLine& line, const LatheAcross& w, double s0, double s1,
                       double side, std::vector<LatheRoot>& out) {
    const LatheSegment& g = o.segments[k];
    const dvec3& c = line.c;
    const dvec3& d = line.d;
    const std::array<double, 4> pr = lathe_piece(g.r, n, s0, s1), py = lathe_piece(g.y, n, s0, s1);
    // F's Bernstein coefficients over the piece from the control values of its factors.
    constexpr int N = 2 * n;
    std::array<double, n + 1> A{}, B{}, E{}, mA{}, mB{}, mE{};
    for (int i = 0; i <= n; ++i) {
        const double q = py[i] - c.y;
        A[i] = d.y * c.x + q * d.x;
        B[i] = d.y * c.z + q * d.z;
        E[i] = d.y * pr[i];
        const double mq = std::abs(py[i]) + std::abs(c.y);
        mA[i] = std::abs(d.y * c.x) + mq * std::abs(d.x);
        mB[i] = std::abs(d.y * c.z) + mq * std::abs(d.z);
        mE[i] = std::abs(E[i]);
    }
    auto binomial = [](int a, int b) {
        double v = 1.0;
        for (int j = 0; j < b; ++j) v = v * double(a - j) / double(j + 1);
        return v;
    };
    std::array<double, N + 1> F{};
    double magnitude = 0.0;
    for (int m = 0; m <= N; ++m) {
        double sum = 0.0, sum_mag = 0.0;
        for (int i = std::max(0, m - n); i <= std::min(n, m); ++i) {
            const int j = m - i;
            const double weight = binomial(n, i) * binomial(n, j) / binomial(N, m);
            sum += weight * (A[i] * A[j] + B[i] * B[j] - E[i] * E[j]);
            sum_mag += weight * (mA[i] * mA[j] + mB[i] * mB[j] + mE[i] * mE[j]);
        }
        F[m] = sum;
        magnitude = std::max(magnitude, sum_mag);
    }
    if (!(magnitude > 0.0)) return;  // the line along the axis, level: no crossing
    // A few roundings per control value (the pieces' de Casteljau too) and per product and sum.
    const double error = 256.0 * bernstein::kEpsilon * magnitude;
    auto value = [&](double u) {
        const double q = bezier_at(py, n, u) - c.y, r = bezier_at(pr, n, u);
        const double a = d.y * c.x + q * d.x, b = d.y * c.z + q * d.z, e = d.y * r;
        return a * a + b * b - e * e;
    };
    auto accept = [&](double u, double, double) {
        const double s = s0 + (s1 - s0) * u;
        double sigma;
        if (side == 0.0) {
            sigma = (bezier_at(g.y, n, s) - c.y) / d.y;
        } else {
            const double r = bezier_at(g.r, n, s), gap = r * r - w.rho0_2;
            if (gap < -64.0 * bernstein::kEpsilon * (r * r + w.rho0_2)) return false;  // the circle misses the line
            sigma = w.middle + side * std::sqrt(std::max(gap, 0.0) / w.across);
        }
        if (sigma > w.s_min && sigma < w.s_max)
            out.push_back({sigma, lathe_normal(o, g, s, c + sigma * d, d), glm::dvec2(double(k), s)});
        return false;
    };
    bernstein::isolate(F, 0.0, 1.0, error, value, accept, true);
}

// The roots on segment k with sigma in (s_min, s_max), appended to `out` (any order). A ray more
// along the axis than across it: F over the whole segment, sigma from y(s). Else the ray's
// stretch through the segment's band is cut at its point nearest the axis, and each half taken
// over the pieces of s where y(s) is monotone and within the half's heights: F's roots come in
// pairs about that point, as close as the ray is level, and the pieces part them (and shrink
// with the half's heights, so that F is resolved on them however level the ray).
template <int n>
void lathe_segment_roots(const Lathe& o, std::size_t k, const LatheLine& line, double s_min, double s_max,
                         std::vector<LatheRoot>& out) {
    const LatheSegment& g = o.segments[k];
    const dvec3& c = line.c;
    const dvec3& d = line.d;
    // Its band: the slab between its lowest and highest control heights, the cylinder of its
    // largest control radius (the curve lies in their convex hull), both widened a little.
    const double widen = 1e-9 * lathe_size(o);
    double lo = s_min, hi = s_max;
    if (d.y != 0.0) {
        double a = (g.y_lo - widen - c.y) / d.y, b = (g.y_hi + widen - c.y) / d.y;
        if (a > b) std::swap(a, b);
        lo = std::max(lo, a);
        hi = std::min(hi, b);
    } else if (c.y < g.y_lo - widen || c.y > g.y_hi + widen) {
        return;
    }
    LatheAcross w{s_min, s_max, 0.0, 0.0, d.x * d.x + d.z * d.z};
    w.middle = w.across > 0.0 ? -(c.x * d.x + c.z * d.z) / w.across : 0.0;
    const double nx = c.x + w.middle * d.x, nz = c.z + w.middle * d.z;
    w.rho0_2 = nx * nx + nz * nz;
    const double R = g.r_max + widen;
    if (w.rho0_2 > R * R) return;
    if (w.across > 0.0) {
        const double reach = std::sqrt((R * R - w.rho0_2) / w.across);
        lo = std::max(lo, w.middle - reach);
        hi = std::min(hi, w.middle + reach);
    }
    if (!(lo <= hi)) return;
    if (w.across == 0.0) {
        // Along the axis: where r(s) is the line's distance from it (F, d.y^2 (rho0^2 - r^2),
        // would square it: a double root where the curve meets the axis).
        const double rho0 = std::sqrt(w.rho0_2);
        std::array<double, n + 1> f{};
        double magnitude = rho0;
        for (int i = 0; i <= n; ++i) {
            f[i] = g.r[i] - rho0;
            magnitude = std::max(magnitude, std::abs(g.r[i]) + rho0);
        }
        auto value = [&](double s) { return bezier_at(g.r, n, s) - rho0; };
        auto accept = [&](double s, double, double) {
            const double sigma = (bezier_at(g.y, n, s) - c.y) / d.y;
            if (sigma > s_min && sigma < s_max) out.push_back({sigma, lathe_normal(o, g, s, c + sigma * d, d), glm::dvec2(double(k), s)});
            return false;
        };
        bernstein::isolate(f, 0.0, 1.0, 8.0 * bernstein::kEpsilon * magnitude, value, accept, true);
        return;
    }
    if (d.y * d.y >= w.across) {
        lathe_piece_roots<n>(o, k, line, w, 0.0, 1.0, 0.0, out);
        return;
    }
    const std::vector<double> ends = lathe_monotone_ends(g.y, n);
    for (double side : {-1.0, 1.0}) {
        const double a = side < 0.0 ? lo : std::max(lo, w.middle), b = side < 0.0 ? std::min(hi, w.middle) : hi;
        if (!(a <= b)) continue;
        const double Ya = c.y + a * d.y, Yb = c.y + b * d.y;
        const double Ylo = std::min(Ya, Yb), Yhi = std::max(Ya, Yb);
        for (std::size_t e = 0; e + 1 < ends.size(); ++e) {
            const double p0 = ends[e], p1 = ends[e + 1];
            const double y0 = bezier_at(g.y, n, p0), y1 = bezier_at(g.y, n, p1);
            if (y0 == y1) {  // level along the piece: a flat ring, which a level line in its plane only grazes
                if (d.y == 0.0 || y0 < Ylo || y0 > Yhi) continue;
                lathe_piece_roots<n>(o, k, line, w, p0, p1, side, out);
                continue;
            }
            const bool rising = y1 > y0;
            const double ylo = std::min(y0, y1), yhi = std::max(y0, y1);
            if (yhi < Ylo || ylo > Yhi) continue;
            const double at_lo = ylo < Ylo ? lathe_height_at(g.y, n, Ylo, p0, p1, y0 > Ylo) : (rising ? p0 : p1);
            const double at_hi = yhi > Yhi ? lathe_height_at(g.y, n, Yhi, p0, p1, y0 > Yhi) : (rising ? p1 : p0);
            lathe_piece_roots<n>(o, k, line, w, std::min(at_lo, at_hi), std::max(at_lo, at_hi), side, out);
        }
    }
}

// Every root with sigma in (s_min, s_max), nearest first, those within rounding of each other one.
std::vector<LatheRoot> lathe_roots(const Lathe& o, const LatheLine& line, double s_min, double s_max) {
    std::vector<LatheRoot> roots;
    for (std::size_t k = 0; k < o.segments.size(); ++k) {
        if (o.degree == 1) lathe_segment_roots<1>(o, k, line, s_min, s_max, roots);
        else if (o.degree == 2) lathe_segment_roots<2>(o, k, line, s_min, s_max, roots);
        else lathe_segment_roots<3>(o, k, line, s_min, s_max, roots);
    }
    std::sort(roots.begin(), roots.end(), [](const LatheRoot& a, const LatheRoot& b) { return a.sigma < b.sigma; });
    const double merge = 1e-9 * lathe_size(o);
    std::vector<LatheRoot> kept;
    for (const LatheRoot& r : roots)
        if (kept.empty() || r.sigma - kept.back().sigma > merge) kept.push_back(r);
    return kept;
}

}  // namespace

std::optional<SurfaceHit> intersect(const Lathe& o, const Ray& ray, double t_min, double t_max) {
    const std::optional<LatheLine> line = lathe_line(ray);
    if (!line || o.segments.empty()) return std::nullopt;
    const double s_min = t_min * line->length - line->tc, s_max = t_max * line->length - line->tc;
    const std::vector<LatheRoot> roots = lathe_roots(o, *line, s_min, s_max);
    if (roots.empty()) return std::nullopt;
    const LatheRoot& first = roots.front();
    SurfaceHit hit{(line->tc + first.sigma) / line->length, first.normal};
    hit.uv = first.uv;
    return hit;
}

std::vector<double> roots_on_line(const Lathe& o, const Ray& ray) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const std::optional<LatheLine> line = lathe_line(ray);
    if (!line || o.segments.empty()) return {};
    std::vector<double> roots;
    for (const LatheRoot& r : lathe_roots(o, *line, -kInfinity, kInfinity)) roots.push_back((line->tc + r.sigma) / line->length);
    return roots;
}

bool inside(const Lathe& o, const dvec3& p) {
    if (!o.closed || !(p.y >= o.y_lo && p.y <= o.y_hi)) return false;
    const double rho = std::hypot(p.x, p.z);
    const int n = o.degree;
    int crossings = 0;
    for (const LatheSegment& g : o.segments) {
        if (p.y < g.y_lo || p.y > g.y_hi || rho >= g.r_max) continue;
        std::array<double, 4> c{};
        double magnitude = 0.0;
        for (int i = 0; i <= n; ++i) {
            c[i] = g.y[i] - p.y;
            magnitude = std::max(magnitude, std::abs(g.y[i]) + std::abs(p.y));
        }
        const double error = 8.0 * bernstein::kEpsilon * magnitude;
        auto value = [&](double s) { return bezier_at(g.y, n, s) - p.y; };
        auto accept = [&](double s, double from, double to) {
            const bool crosses = from == to || ((value(from) > 0.0) != (value(to) > 0.0));
            if (crosses && bezier_at(g.r, n, s) > rho) ++crossings;
            return false;
        };
        if (n == 1) bernstein::isolate(std::array<double, 2>{c[0], c[1]}, 0.0, 1.0, error, value, accept, true);
        else if (n == 2) bernstein::isolate(std::array<double, 3>{c[0], c[1], c[2]}, 0.0, 1.0, error, value, accept, true);
        else bernstein::isolate(c, 0.0, 1.0, error, value, accept, true);
    }
    return (crossings & 1) != 0;
}

// u the angle about y from +x toward +z over 2 pi in [0, 1), v POV-Ray's: (segment + s) over the
// segment count.
glm::dvec2 texture_uv(const Lathe& o, const dvec3& p, const glm::dvec2& hit_uv) {
    double angle = (p.x == 0.0 && p.z == 0.0) ? 0.0 : std::atan2(p.z, p.x);
    if (angle < 0.0) angle += 2.0 * M_PI;
    double u = angle / (2.0 * M_PI);
    if (u >= 1.0) u = 0.0;
    const double count = double(std::max<std::size_t>(o.segments.size(), 1));
    return {u, std::clamp((hit_uv.x + hit_uv.y) / count, 0.0, 1.0)};
}

}  // namespace lancer::cpu

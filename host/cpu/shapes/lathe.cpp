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
// The ray's sigma at a root s: where the ray runs more along the axis than across it,
// (y(s) - c.y) / d.y; else from the circle of radius r(s) the ray crosses, sigma_m +- reach
// about its point nearest the axis, the one nearer (y(s) - c.y) / d.y, or both where the root
// was only told to within rounding (a ray level within rounding, for which F is a square whose
// double roots are each the two crossings of the circle at that height: POV-Ray's special case
// of the horizontal ray). Roots of neighbouring segments at their shared point, and the two
// candidates of a root that touches, are merged when within 1e-9 of the lathe's size.
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

// The Bezier curve of degree n with control values b at s (de Casteljau), and its derivative.
double lathe_at(const std::array<double, 4>& b, int n, double s) {
    std::array<double, 4> w = b;
    for (int level = n; level > 0; --level)
        for (int i = 0; i < level; ++i) w[i] = (1.0 - s) * w[i] + s * w[i + 1];
    return w[0];
}
double lathe_derivative(const std::array<double, 4>& b, int n, double s) {
    std::array<double, 4> d{};
    for (int i = 0; i < n; ++i) d[i] = n * (b[i + 1] - b[i]);
    return lathe_at(d, n - 1, s);
}

double lathe_size(const Lathe& o) { return std::max({o.r_max, std::abs(o.y_lo), std::abs(o.y_hi)}); }

// The outward unit normal at the curve's parameter s (the segment's side of (y', -r'), turned
// about the axis to the point p); on the axis, along it. Where the curve's tangent vanishes (a
// repeated control point at an end), its chord's.
dvec3 lathe_normal(const Lathe& o, const LatheSegment& g, double s, const dvec3& p, const dvec3& d) {
    const int n = o.degree;
    double rp = lathe_derivative(g.r, n, s), yp = lathe_derivative(g.y, n, s);
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

// The roots of F on segment k with sigma in (s_min, s_max), appended to `out` (any order).
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
    const double across = d.x * d.x + d.z * d.z;
    const double R = g.r_max + widen;
    const double middle = across > 0.0 ? -(c.x * d.x + c.z * d.z) / across : 0.0;  // nearest the axis
    const double nx = c.x + middle * d.x, nz = c.z + middle * d.z;
    const double rho0_2 = nx * nx + nz * nz;  // the line's distance from the axis, squared
    if (rho0_2 > R * R) return;
    if (across > 0.0) {
        const double reach = std::sqrt((R * R - rho0_2) / across);
        lo = std::max(lo, middle - reach);
        hi = std::min(hi, middle + reach);
    }
    if (!(lo <= hi)) return;

    // F's Bernstein coefficients over [0, 1] from the control values of its factors.
    constexpr int N = 2 * n;
    std::array<double, n + 1> A{}, B{}, E{}, mA{}, mB{}, mE{};
    for (int i = 0; i <= n; ++i) {
        const double q = g.y[i] - c.y;
        A[i] = d.y * c.x + q * d.x;
        B[i] = d.y * c.z + q * d.z;
        E[i] = d.y * g.r[i];
        const double mq = std::abs(g.y[i]) + std::abs(c.y);
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
            const double w = binomial(n, i) * binomial(n, j) / binomial(N, m);
            sum += w * (A[i] * A[j] + B[i] * B[j] - E[i] * E[j]);
            sum_mag += w * (mA[i] * mA[j] + mB[i] * mB[j] + mE[i] * mE[j]);
        }
        F[m] = sum;
        magnitude = std::max(magnitude, sum_mag);
    }
    // A few roundings per control value and per product and sum: 256 is generous.
    const double error = 256.0 * bernstein::kEpsilon * magnitude;
    if (!(magnitude > 0.0)) return;  // d.y = 0 and the line along the axis: no crossing

    auto value = [&](double s) {
        const double q = lathe_at(g.y, n, s) - c.y, r = lathe_at(g.r, n, s);
        const double a = d.y * c.x + q * d.x, b = d.y * c.z + q * d.z, e = d.y * r;
        return a * a + b * b - e * e;
    };
    const bool steep = d.y * d.y >= across;
    auto push = [&](double sigma, double s) {
        if (!(sigma > s_min && sigma < s_max)) return;
        out.push_back({sigma, lathe_normal(o, g, s, c + sigma * d, d), glm::dvec2(double(k), s)});
    };
    auto accept = [&](double s, double from, double to) {
        const double q = lathe_at(g.y, n, s) - c.y;
        if (steep) {
            push(q / d.y, s);
            return false;
        }
        const double r = lathe_at(g.r, n, s);
        const double reach = std::sqrt(std::max(r * r - rho0_2, 0.0) / across);
        const double near = middle - reach, far = middle + reach;
        if (from == to && d.y != 0.0) {
            const double sigma_y = q / d.y;
            push(std::abs(near - sigma_y) <= std::abs(far - sigma_y) ? near : far, s);
        } else {
            push(near, s);
            if (far > near) push(far, s);
        }
        return false;
    };
    bernstein::isolate(F, 0.0, 1.0, error, value, accept, true);
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
        auto value = [&](double s) { return lathe_at(g.y, n, s) - p.y; };
        auto accept = [&](double s, double from, double to) {
            const bool crosses = from == to || ((value(from) > 0.0) != (value(to) > 0.0));
            if (crosses && lathe_at(g.r, n, s) > rho) ++crossings;
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

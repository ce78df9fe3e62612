// Ray/superellipsoid (POV-Ray's superellipsoid { <e, n> }) for the CPU reference, in double
// precision, written apart from its GLSL.
//
// In its own coordinates the solid is g = (|x|^p + |y|^p)^(q/p) + |z|^q <= 1, p = 2/e, q = 2/n,
// both at least 1 (e, n in [0.001, 2]). F = g^(1/q) = || (||(x, y)||_p, z) ||_q is a norm (a
// q-norm, increasing in its nonnegative arguments, of a p-norm and |z|), so F along any line is
// convex, the surface F = 1 is g = 1, and F >= max(|x|, |y|, |z|): F > 1 on the faces of the box
// [-B, B]^3, B > 1. Each norm of a pair is evaluated from its larger member m as
// m (1 + (small / m)^p)^(1/p), which neither overflows nor underflows for exponents up to 2000,
// and its partial derivatives are ratios to the power p - 1, all at most 1.
//
// Along the line c + s d (|d| = 1, c its point nearest the origin), clipped to the box and to
// (t_min, t_max): where the stretch's start is outside (F > 1), Newton's method on F(s) = 1 from
// there climbs monotonically toward the first root without passing it (F lies above each of
// its tangents; at a kink of |x| with p = 1 a subgradient serves as well); where the tangent's
// slope is no longer negative while F > 1, F stays above 1 beyond (convexity): a miss. Where the
// start is inside, the hit is the exit: the same from the stretch's end, backward. The root is
// then bracketed, F > 1 at one end and F <= 1 at the other, and halved to double precision. A
// line that touches the surface within rounding (F's minimum 1 to 1e-13) is a hit at the point
// of contact, as the other shapes' touching rays are.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

constexpr double kBoxReach = 1.0 + 1e-6;  // the box the line is clipped to: F > 1 on its faces
constexpr int kNewtonSteps = 200;         // a tangent ray converges linearly: about 55 halvings
constexpr double kTouching = 1e-13;       // F's excess over 1 at a point of contact, within rounding

// A norm of a pair of nonnegative numbers, with exponent k >= 1, and its partial derivatives.
struct PairNorm {
    double value = 0.0, d_a = 0.0, d_b = 0.0;
};

PairNorm pair_norm(double a, double b, double k) {
    const double big = std::max(a, b), small = std::min(a, b);
    if (big == 0.0) return {0.0, k == 1.0 ? 1.0 : 0.0, k == 1.0 ? 1.0 : 0.0};
    const double ratio = small / big;
    const double power = ratio > 0.0 ? std::pow(ratio, k) : 0.0;  // (small / big)^k
    const double sum = 1.0 + power;
    PairNorm out;
    out.value = big * std::pow(sum, 1.0 / k);
    // d/d(big) = (big / value)^(k - 1) = sum^(-(k - 1) / k); d/d(small) = ratio^(k - 1) times that.
    const double d_big = std::pow(sum, -(k - 1.0) / k);
    const double d_small = (ratio > 0.0 ? std::pow(ratio, k - 1.0) : (k == 1.0 ? 1.0 : 0.0)) * d_big;
    out.d_a = a >= b ? d_big : d_small;
    out.d_b = a >= b ? d_small : d_big;
    return out;
}

double sign_of(double v) { return v > 0.0 ? 1.0 : v < 0.0 ? -1.0 : 0.0; }

struct Level {
    double f;        // F at the point
    dvec3 gradient;  // a (sub)gradient of F there
};

struct Exponents {
    double p, q;
};

Level level(const Exponents& k, const dvec3& x) {
    const PairNorm across = pair_norm(std::abs(x.x), std::abs(x.y), k.p);
    const PairNorm whole = pair_norm(across.value, std::abs(x.z), k.q);
    return {whole.value, dvec3(whole.d_a * across.d_a * sign_of(x.x), whole.d_a * across.d_b * sign_of(x.y),
                               whole.d_b * sign_of(x.z))};
}

// Halves [outside, inside] (F > 1 at s = outside, F <= 1 at s = inside) along a + s d down to
// adjacent doubles; the inside end.
double refined(const Exponents& k, const dvec3& a, const dvec3& d, double outside, double inside) {
    for (int i = 0; i < 200; ++i) {
        const double middle = 0.5 * (outside + inside);
        if (middle == outside || middle == inside) break;
        if (level(k, a + middle * d).f > 1.0) outside = middle;
        else inside = middle;
    }
    return inside;
}

// From a, where F > 1, along the unit direction d: the first s in (0, span] where F = 1, or
// nothing where the line does not come inside there.
std::optional<double> first_root(const Exponents& k, const dvec3& a, const dvec3& d, double span, Level at) {
    double s = 0.0;
    for (int i = 0; i < kNewtonSteps; ++i) {
        const double slope = glm::dot(at.gradient, d);
        if (!(slope < 0.0)) return at.f - 1.0 <= kTouching ? std::optional<double>(s) : std::nullopt;
        double next = s + (at.f - 1.0) / -slope;
        if (!(next > s)) next = std::nextafter(s, std::numeric_limits<double>::infinity());
        if (next > span) return std::nullopt;
        const Level there = level(k, a + next * d);
        if (there.f <= 1.0) return refined(k, a, d, s, next);
        if (next - s <= 4e-16 * (1.0 + next)) {
            // Converged to rounding onto a point still outside: the root is just beyond, or the
            // line touches the surface here. Look a little further for the inside.
            for (double w = 4e-16 * (1.0 + next); w <= 1e-9 && next + w <= span; w *= 4.0)
                if (level(k, a + (next + w) * d).f <= 1.0) return refined(k, a, d, next, next + w);
            return there.f - 1.0 <= kTouching ? std::optional<double>(next) : std::nullopt;
        }
        s = next;
        at = there;
    }
    return std::nullopt;
}

}  // namespace

std::optional<SurfaceHit> intersect(const Superellipsoid& o, const Ray& ray, double t_min, double t_max) {
    const double length = glm::length(ray.dir);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    const Exponents k{2.0 / o.e, 2.0 / o.n};
    // The line about its point nearest the centre: u = t length - tc.
    const dvec3 d = ray.dir / length;
    const double tc = -glm::dot(ray.origin, d);
    const dvec3 c = ray.origin + tc * d;
    double lo = t_min * length - tc, hi = t_max * length - tc;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) {
            if (std::abs(c[i]) > kBoxReach) return std::nullopt;
            continue;
        }
        const double a = (-kBoxReach - c[i]) / d[i], b = (kBoxReach - c[i]) / d[i];
        lo = std::max(lo, std::min(a, b));
        hi = std::min(hi, std::max(a, b));
    }
    if (!(lo < hi)) return std::nullopt;
    auto hit_at = [&](double u) -> std::optional<SurfaceHit> {
        const double t = (tc + u) / length;
        if (!(t > t_min && t < t_max)) return std::nullopt;
        const dvec3 x = c + u * d;
        const dvec3 g = level(k, x).gradient;
        const double size = glm::length(g);
        return SurfaceHit{t, size > 0.0 ? g / size : -d, texture_uv(o, x)};
    };
    const dvec3 start = c + lo * d;
    const Level at_start = level(k, start);
    if (at_start.f > 1.0) {
        // Outside at the stretch's start: the first root, if any, is the hit (the exit is beyond).
        const auto s = first_root(k, start, d, hi - lo, at_start);
        if (!s) return std::nullopt;
        if (auto hit = hit_at(lo + *s)) return hit;
        // The entry is at t_min to rounding: the exit is the next surface.
    }
    // Inside at the start: the exit, found backward from the stretch's end, if that is outside.
    const dvec3 end = c + hi * d;
    const Level at_end = level(k, end);
    if (!(at_end.f > 1.0)) return std::nullopt;
    const auto s = first_root(k, end, -d, hi - lo, at_end);
    if (!s) return std::nullopt;
    return hit_at(hi - *s);
}

glm::dvec2 texture_uv(const Superellipsoid&, const dvec3& p) { return {(p.x + 1.01) / 2.02, (p.y + 1.01) / 2.02}; }

}  // namespace lancer::cpu

// Ray/torus (POV-Ray's torus) for the CPU reference, in double precision, written apart from
// shaders/shapes/torus.glsl (which splits the ray at the quartic's critical points and runs
// Newton in float).
//
// In the torus's frame (y along the axis), scaled by S = R + r so that the surface lies in the
// unit ball (a = R / S, b = r / S, a + b = 1), the surface is
//   f(p) = (|p|^2 + a^2 - b^2)^2 - 4 a^2 (x^2 + z^2) = h-(p) h+(p),
//   h-(p) = (rho - a)^2 + y^2 - b^2,   h+(p) = (rho + a)^2 + y^2 - b^2,   rho^2 = x^2 + z^2:
// h- = 0 is the tube about the circle (the whole ring torus, the spindle's outer "apple"), h+ = 0
// its mirror through the axis (the spindle's inner "lemon", empty for b < a). Along the ray, cut
// to the unit ball and the slab |y| <= b, f is a quartic g(tau), tau in [-1, 1] over the segment,
// whose roots are isolated by Bernstein subdivision (cpu/shapes/bernstein_roots.hpp: a piece is
// dropped only on a proof that g keeps one sign over it), each found by bisection on f's factored
// form (accurate near the surface); a piece of 1e-12 of the segment whose coefficients still
// straddle 0 is a touching point (a ray tangent to the tube, or through a spindle's cusp): a hit.
#include <algorithm>
#include <array>
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

constexpr double kMargin = 1e-9;  // the ball and slab widened (scaled units): the surface touches the ball

struct TorusFrame {
    dvec3 o, d;      // the ray in the scaled frame: o + sigma d, |d| = 1
    double a, b;     // the radii over S
    double to_t;     // t = sigma * to_t
};

double f_factored(const TorusFrame& fr, const dvec3& p) {
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    const double y2b2 = (p.y - fr.b) * (p.y + fr.b);
    const double minus = (rho - fr.a) * (rho - fr.a) + y2b2;
    const double plus = (rho + fr.a) * (rho + fr.a) + y2b2;
    return minus * plus;
}

// The gradient of f = h- h+ in the scaled frame, from the factors (each accurate near its zero).
dvec3 gradient(double a, double b, const dvec3& p) {
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    const double y2b2 = (p.y - b) * (p.y + b);
    const double minus = (rho - a) * (rho - a) + y2b2, plus = (rho + a) * (rho + a) + y2b2;
    // grad h-+ = 2 ((rho -+ a) x / rho, y, (rho -+ a) z / rho); at rho = 0 the radial part's
    // direction is undefined (a spindle's cusp) and left out.
    const double cx = rho > 0.0 ? p.x / rho : 0.0, cz = rho > 0.0 ? p.z / rho : 0.0;
    const dvec3 gm((rho - a) * cx, p.y, (rho - a) * cz), gp((rho + a) * cx, p.y, (rho + a) * cz);
    return plus * gm + minus * gp;
}

// The torus's scaled frame (a + b = 1) for a ray, or none for a degenerate ray or torus.
std::optional<TorusFrame> frame_of(const Torus& o, const Ray& ray) {
    const double S = o.major_radius + o.minor_radius;
    const double length = glm::length(ray.dir);
    if (!(length > 0.0) || !(S > 0.0)) return std::nullopt;
    const dvec3 u = o.u_axis, ax = o.axis, v = glm::cross(o.u_axis, o.axis);
    const dvec3 e = ray.origin - o.center;
    TorusFrame fr;
    fr.o = dvec3(glm::dot(e, u), glm::dot(e, ax), glm::dot(e, v)) / S;
    fr.d = dvec3(glm::dot(ray.dir, u), glm::dot(ray.dir, ax), glm::dot(ray.dir, v)) / length;
    fr.a = o.major_radius / S;
    fr.b = o.minor_radius / S;
    fr.to_t = S / length;
    return fr;
}

// The roots along the ray with t in (t_min, t_max), nearest first (only the nearest, or all):
// t and the gradient of f there (in the scaled frame).
std::vector<std::pair<double, dvec3>> torus_roots(const Torus& o, const Ray& ray, double t_min, double t_max, bool nearest_only) {
    const std::optional<TorusFrame> frame = frame_of(o, ray);
    if (!frame) return {};
    const TorusFrame& fr = *frame;

    // The segment: the unit ball and the slab |y| <= b, within (t_min, t_max), relative to the
    // ray's point nearest the centre.
    const double tc = -glm::dot(fr.o, fr.d);
    const dvec3 c = fr.o + tc * fr.d;
    const double ball = 1.0 + kMargin;
    // c is the nearest point to the rounding of fr.o + tc fr.d, which is of |fr.o|: its c.d kept.
    const double beta0 = glm::dot(c, fr.d);
    const double reach2 = beta0 * beta0 + ball * ball - glm::dot(c, c);
    if (!(reach2 >= 0.0)) return {};
    double lo = -std::sqrt(reach2) - beta0, hi = std::sqrt(reach2) - beta0;
    const double slab = fr.b + kMargin;
    if (fr.d.y != 0.0) {
        double y0 = (-slab - c.y) / fr.d.y, y1 = (slab - c.y) / fr.d.y;
        if (y0 > y1) std::swap(y0, y1);
        lo = std::max(lo, y0);
        hi = std::min(hi, y1);
    } else if (std::abs(c.y) > slab) {
        return {};
    }
    lo = std::max(lo, t_min / fr.to_t - tc);
    hi = std::min(hi, t_max / fr.to_t - tc);
    if (!(lo < hi)) return {};

    // g(tau) = f(P + half tau D), P the segment's middle.
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    const dvec3 P = c + mid * fr.d, D = fr.d;
    const double a2 = fr.a * fr.a, k = (fr.a - fr.b) * (fr.a + fr.b);
    // q(tau) = |p|^2 + a^2 - b^2 and rho^2(tau), as quadratics in tau.
    const double q0 = glm::dot(P, P) + k, q1 = 2.0 * half * glm::dot(P, D), q2 = half * half;
    const double r0 = P.x * P.x + P.z * P.z, r1 = 2.0 * half * (P.x * D.x + P.z * D.z),
                 r2 = half * half * (D.x * D.x + D.z * D.z);
    // f = q^2 - 4 a^2 rho^2: power coefficients, and the sums of their terms' magnitudes.
    bernstein::Quartic p{}, m{};
    p[0] = f_factored(fr, P);
    m[0] = q0 * q0 + 4.0 * a2 * r0;
    p[1] = 2.0 * q0 * q1 - 4.0 * a2 * r1;
    m[1] = std::abs(2.0 * q0 * q1) + std::abs(4.0 * a2 * r1);
    p[2] = q1 * q1 + 2.0 * q0 * q2 - 4.0 * a2 * r2;
    m[2] = q1 * q1 + std::abs(2.0 * q0 * q2) + 4.0 * a2 * r2;
    p[3] = 2.0 * q1 * q2;
    m[3] = std::abs(p[3]);
    p[4] = q2 * q2;
    m[4] = p[4];
    const bernstein::Form bern = bernstein::from_power(p, m);
    // Each coefficient carries a few dozen roundings of the magnitudes it was formed from (the
    // ray's frame, q and rho^2, their products, two changes of basis): 256 is generous.
    const double error = 256.0 * bernstein::kEpsilon * bern.magnitude;

    // tau from -1 to 1 is sigma from mid - half to mid + half about tc.
    auto sigma = [&](double tau) { return tc + mid + half * tau; };
    std::vector<double> taus;
    auto accept = [&](double tau, double, double) {
        const double t = sigma(tau) * fr.to_t;
        if (!(t > t_min && t < t_max)) return false;
        taus.push_back(tau);
        return nearest_only;
    };
    auto value = [&](double tau) { return f_factored(fr, P + (half * tau) * D); };
    bernstein::isolate(bern.c, -1.0, 1.0, error, value, accept);
    std::vector<std::pair<double, dvec3>> roots;
    for (double tau : taus) roots.emplace_back(sigma(tau) * fr.to_t, gradient(fr.a, fr.b, P + (half * tau) * D));
    return roots;
}

// The scaled frame's gradient as a world unit normal (a cusp of a spindle has no tangent plane: the axis).
dvec3 world_normal(const Torus& o, const dvec3& g) {
    const dvec3 normal = g.x * o.u_axis + g.y * o.axis + g.z * glm::cross(o.u_axis, o.axis);
    const double length = glm::length(normal);
    return length > 0.0 ? normal / length : o.axis;
}

}  // namespace

std::optional<SurfaceHit> intersect(const Torus& o, const Ray& ray, double t_min, double t_max) {
    const auto roots = torus_roots(o, ray, t_min, t_max, true);
    if (roots.empty()) return std::nullopt;
    return SurfaceHit{roots.front().first, world_normal(o, roots.front().second)};
}

std::vector<double> roots_on_line(const Torus& o, const Ray& ray) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    std::vector<double> roots;
    for (const auto& root : torus_roots(o, ray, -kInfinity, kInfinity, false)) roots.push_back(root.first);
    return roots;
}

// f < 0, from its factored form (the factors are accurate near their zeros).
bool inside(const Torus& o, const dvec3& p) {
    const auto fr = frame_of(o, Ray{p, o.axis});
    return fr && f_factored(*fr, fr->o) < 0.0;
}

// u the angle about the axis from u_axis toward v_axis, v the angle around the tube from its
// outer equator toward +axis, both over 2 pi in [0, 1).
glm::dvec2 texture_uv(const Torus& o, const dvec3& p) {
    const dvec3 w = p - o.center;
    const double x = glm::dot(w, o.u_axis), z = glm::dot(w, o.v_axis), y = glm::dot(w, o.axis);
    auto turn = [](double sine, double cosine) {
        double angle = (sine == 0.0 && cosine == 0.0) ? 0.0 : std::atan2(sine, cosine);
        if (angle < 0.0) angle += 2.0 * M_PI;
        double f = angle / (2.0 * M_PI);
        return f >= 1.0 ? 0.0 : f;
    };
    const double rho = std::sqrt(x * x + z * z);
    return {turn(z, x), turn(y, rho - o.major_radius)};
}

}  // namespace lancer::cpu

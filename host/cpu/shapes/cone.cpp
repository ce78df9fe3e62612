// Ray/cone and ray/cylinder (POV-Ray's cone and cylinder, one shape): in the cone's own frame
// (x along u_axis, y along v_axis, z along the axis from the base), the side is
// x^2 + y^2 = r(z)^2 with r(z) = base_radius + k z, k = (cap_radius - base_radius) / h, for z in
// [0, h]; each end of non-zero radius is closed by a disc across the axis unless the cone is open.
// The quadratic along the ray is solved without cancellation: its discriminant is a difference of two
// squares formed from the ray's parts across the axis, and the roots are q / A and C / q with
// q = -(b + sign(b) sqrt(disc)). Independent of shaders/shapes/cone.glsl, which works with world
// vectors instead of frame coordinates.
#include <cmath>

#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

struct Frame {
    dvec3 axis;  // unit, from base to cap
    double h;    // the axis's length
    double k;    // the radius's change per unit of z
};

Frame frame_of(const Cone& c) {
    const dvec3 along = c.cap - c.base;
    const double h = glm::length(along);
    return {along / h, h, (c.cap_radius - c.base_radius) / h};
}

}  // namespace

std::optional<SurfaceHit> intersect(const Cone& c, const Ray& ray, double t_min, double t_max) {
    const Frame fr = frame_of(c);
    // Measured from the ray's point nearest the base, s along the ray from there: the terms below
    // are then of the cone's size for any ray that can hit it, however far its origin (from far
    // off, a pointed cone's other nappe, which the quadratic includes, passes near the origin).
    const double shift = glm::dot(c.base - ray.origin, ray.dir);
    const dvec3 w = ray.origin + shift * ray.dir - c.base;
    // The origin and direction in the frame (u_axis, v_axis, axis).
    const double ox = glm::dot(w, c.u_axis), oy = glm::dot(w, c.v_axis), oz = glm::dot(w, fr.axis);
    const double dx = glm::dot(ray.dir, c.u_axis), dy = glm::dot(ray.dir, c.v_axis), dz = glm::dot(ray.dir, fr.axis);

    double best = t_max - shift;
    const double s_min = t_min - shift;
    int part = -1;  // 0 the side, 1 the base's disc, 2 the cap's
    auto consider = [&](double s, int which) {
        if (s > s_min && s < best) {
            best = s;
            part = which;
        }
    };

    // The side: (ox + s dx)^2 + (oy + s dy)^2 = (R + s K)^2, R the radius at o's z (o the ray's
    // point at the shift). A s^2 + 2 b s + C = 0 with A = dx^2 + dy^2 - K^2, b = ox dx + oy dy - R K,
    // C = ox^2 + oy^2 - R^2, and b^2 - A C = (R dx - K ox)^2 + (R dy - K oy)^2 - (ox dy - oy dx)^2.
    const double R = c.base_radius + fr.k * oz, K = fr.k * dz;
    const double ex = R * dx - K * ox, ey = R * dy - K * oy, cross = ox * dy - oy * dx;
    const double disc = ex * ex + ey * ey - cross * cross;
    if (disc >= 0.0) {
        const double d_across = std::hypot(dx, dy), o_across = std::hypot(ox, oy);
        const double A = (d_across - std::abs(K)) * (d_across + std::abs(K));
        const double b = ox * dx + oy * dy - R * K;
        const double C = (o_across - std::abs(R)) * (o_across + std::abs(R));
        const double q = -(b + std::copysign(std::sqrt(disc), b));
        auto on_side = [&](double s) {
            const double z = oz + s * dz;
            if (z >= 0.0 && z <= fr.h) consider(s, 0);
        };
        if (A != 0.0) on_side(q / A);
        if (q != 0.0) on_side(C / q);
    }

    // The ends: planes z = 0 and z = h, within their radius.
    if (!c.open && dz != 0.0) {
        const double ends[2] = {0.0, fr.h};
        const double radii[2] = {c.base_radius, c.cap_radius};
        for (int e = 0; e < 2; ++e) {
            if (!(radii[e] > 0.0)) continue;  // a point: no disc
            const double s = (ends[e] - oz) / dz;
            const double x = ox + s * dx, y = oy + s * dy;
            if (x * x + y * y <= radii[e] * radii[e]) consider(s, 1 + e);
        }
    }
    if (part < 0) return std::nullopt;
    const double t = shift + best;
    if (!(t > t_min && t < t_max)) return std::nullopt;  // the sum's rounding

    SurfaceHit hit{t, dvec3(0.0), {double(part), 0.0}};
    if (part == 1) {
        hit.normal = -fr.axis;
    } else if (part == 2) {
        hit.normal = fr.axis;
    } else {
        // The gradient of x^2 + y^2 - r(z)^2 is 2 (x, y, -k r(z)): outward radial minus k along the
        // axis, once both are divided by r(z) = sqrt(x^2 + y^2).
        const double x = ox + best * dx, y = oy + best * dy;
        const double rho = std::hypot(x, y);
        const dvec3 radial = rho > 0.0 ? (x * c.u_axis + y * c.v_axis) / rho : c.u_axis;  // the apex: any
        hit.normal = glm::normalize(radial - fr.k * fr.axis);
    }
    return hit;
}

// u the angle about the axis from u_axis toward v_axis over 2 pi, in [0, 1); v along the side from
// 0 at the base to 1 at the cap, on an end's disc from 0 at its centre to 1 at its rim. `part` is
// the hit's (its uv.x: 0 the side, 1 the base's disc, 2 the cap's).
glm::dvec2 texture_uv(const Cone& c, const dvec3& p, int part) {
    const Frame fr = frame_of(c);
    const dvec3 w = p - c.base;
    const double x = glm::dot(w, c.u_axis), y = glm::dot(w, c.v_axis);
    double angle = (x == 0.0 && y == 0.0) ? 0.0 : std::atan2(y, x);
    if (angle < 0.0) angle += 2.0 * M_PI;
    double u = angle / (2.0 * M_PI);
    if (u >= 1.0) u = 0.0;
    if (part == 0) return {u, glm::dot(w, fr.axis) / fr.h};
    const double radius = part == 1 ? c.base_radius : c.cap_radius;
    return {u, std::hypot(x, y) / radius};
}

}  // namespace lancer::cpu

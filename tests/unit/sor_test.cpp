// The reference's surface of revolution (host/cpu/shapes/sor.cpp): where r^2 is of degree 2 at
// most (cylinders, cones, paraboloids, spheres, hyperboloids) against the quadric it is, solved
// here in closed form; a cubic spline against a march of its inside, evaluated here apart from
// the segments' coefficients (from the spline's Hermite form); open against closed; the ray's
// own parameter, far from the origin, and the texture mapping.
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace sor_test {  // its own names in the unity build
namespace {

constexpr double kFar = 1e30;

// The largest radius of a segment: r^2 = ((a u + b) u + c) u + d over u in [0, y1 - y0], at the
// ends or where its slope is 0.
void set_r_max(SorSegment& s) {
    const double length = s.y1 - s.y0;
    auto r2 = [&](double u) { return ((s.a * u + s.b) * u + s.c) * u + s.d; };
    double most = std::max(r2(0.0), r2(length));
    // 3 a u^2 + 2 b u + c = 0
    const double A = 3.0 * s.a, B = 2.0 * s.b, C = s.c;
    std::vector<double> critical;
    if (A == 0.0) {
        if (B != 0.0) critical.push_back(-C / B);
    } else if (B * B - 4.0 * A * C >= 0.0) {
        const double root = std::sqrt(B * B - 4.0 * A * C);
        critical.push_back((-B - root) / (2.0 * A));
        critical.push_back((-B + root) / (2.0 * A));
    }
    for (double u : critical)
        if (u > 0.0 && u < length) most = std::max(most, r2(u));
    s.r_max = std::sqrt(std::max(most, 0.0));
}

// The discs and the largest radius from the segments.
Sor finish(std::vector<SorSegment> segments, bool open) {
    Sor o;
    o.segments = std::move(segments);
    o.open = open;
    const SorSegment &first = o.segments.front(), &last = o.segments.back();
    o.base_r2 = std::max(first.d, 0.0);
    const double top = last.y1 - last.y0;
    o.cap_r2 = std::max(((last.a * top + last.b) * top + last.c) * top + last.d, 0.0);
    o.r_max = 0.0;
    for (const SorSegment& s : o.segments) o.r_max = std::max(o.r_max, s.r_max);
    return o;
}

// r^2 = q0 + q1 y + q2 y^2 + q3 y^3 in the sor's y.
struct Cubic {
    double q0 = 0.0, q1 = 0.0, q2 = 0.0, q3 = 0.0;
    double operator()(double y) const { return ((q3 * y + q2) * y + q1) * y + q0; }
};

// The sor of r^2 = q(y) cut into segments at the heights ys (ascending), each re-expanded about
// its own bottom.
Sor sor_of(const Cubic& q, const std::vector<double>& ys, bool open = false) {
    std::vector<SorSegment> segments;
    for (std::size_t i = 0; i + 1 < ys.size(); ++i) {
        SorSegment s;
        s.y0 = ys[i];
        s.y1 = ys[i + 1];
        const double y = s.y0;
        s.a = q.q3;
        s.b = 3.0 * q.q3 * y + q.q2;
        s.c = (3.0 * q.q3 * y + 2.0 * q.q2) * y + q.q1;
        s.d = q(y);
        set_r_max(s);
        segments.push_back(s);
    }
    return finish(std::move(segments), open);
}

// A knot of a spline of r^2: its height, r^2 and the slope of r^2 there.
struct Knot {
    double y, r2, slope;
};

// The Hermite cubic of r^2 between consecutive knots, as segments.
Sor spline(const std::vector<Knot>& knots, bool open = false) {
    std::vector<SorSegment> segments;
    for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
        const Knot &k0 = knots[i], &k1 = knots[i + 1];
        const double L = k1.y - k0.y, rise = (k1.r2 - k0.r2) / L;
        SorSegment s;
        s.y0 = k0.y;
        s.y1 = k1.y;
        s.d = k0.r2;
        s.c = k0.slope;
        s.b = (3.0 * rise - 2.0 * k0.slope - k1.slope) / L;
        s.a = (k0.slope + k1.slope - 2.0 * rise) / (L * L);
        set_r_max(s);
        segments.push_back(s);
    }
    return finish(std::move(segments), open);
}

// r^2 of the spline at y from the Hermite basis (apart from the segments' coefficients).
double spline_r2(const std::vector<Knot>& knots, double y) {
    std::size_t i = 0;
    while (i + 2 < knots.size() && y > knots[i + 1].y) ++i;
    const Knot &k0 = knots[i], &k1 = knots[i + 1];
    const double L = k1.y - k0.y, s = (y - k0.y) / L;
    const double h00 = (1.0 + 2.0 * s) * (1.0 - s) * (1.0 - s), h10 = s * (1.0 - s) * (1.0 - s);
    const double h01 = s * s * (3.0 - 2.0 * s), h11 = s * s * (s - 1.0);
    return h00 * k0.r2 + h10 * L * k0.slope + h01 * k1.r2 + h11 * L * k1.slope;
}

// A crossing of the quadric sor's surface along the line: t and the outward unit normal.
struct Crossing {
    double t;
    dvec3 normal;
};

// Every crossing of the line with the sor of r^2 = q0 + q1 y + q2 y^2 over [bottom, top] (its
// discs too, where they have a radius, unless open), in closed form, sorted.
std::vector<Crossing> quadric_crossings(const Cubic& q, double bottom, double top, bool open, const Ray& ray) {
    const dvec3 o = ray.origin, d = ray.dir;
    // f(t) = x^2 + z^2 - r^2(y) = A t^2 + B t + C.
    const double A = d.x * d.x + d.z * d.z - q.q2 * d.y * d.y;
    const double B = 2.0 * (o.x * d.x + o.z * d.z) - 2.0 * q.q2 * o.y * d.y - q.q1 * d.y;
    const double C = o.x * o.x + o.z * o.z - q(o.y);
    std::vector<double> ts;
    if (A == 0.0) {
        if (B != 0.0) ts.push_back(-C / B);
    } else {
        const double disc = B * B - 4.0 * A * C;
        if (disc >= 0.0) {
            const double h = -0.5 * (B + std::copysign(std::sqrt(disc), B));
            if (h != 0.0) {
                ts.push_back(h / A);
                ts.push_back(C / h);
            } else {
                ts.push_back(0.0);
            }
        }
    }
    std::vector<Crossing> crossings;
    for (double t : ts) {
        const dvec3 p = o + t * d;
        if (p.y < bottom || p.y > top) continue;
        crossings.push_back({t, glm::normalize(dvec3(2.0 * p.x, -(2.0 * q.q2 * p.y + q.q1), 2.0 * p.z))});
    }
    if (!open && d.y != 0.0) {
        for (const auto& [y, ny] : {std::pair{bottom, -1.0}, std::pair{top, 1.0}}) {
            const double t = (y - o.y) / d.y;
            const dvec3 p = o + t * d;
            if (q(y) > 0.0 && p.x * p.x + p.z * p.z <= q(y)) crossings.push_back({t, dvec3(0, ny, 0)});
        }
    }
    std::sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
    return crossings;
}

// A random point of the quadric sor's surface: of its curve where r^2 > 0, or of a disc.
dvec3 surface_point(const Cubic& q, double bottom, double top, bool discs, std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double angle = 2.0 * M_PI * unit(rng);
    const double pick = unit(rng);
    const double y_disc = pick < 0.15 ? bottom : top;
    if (discs && pick < 0.3 && q(y_disc) > 0.0) {  // (a disc of radius 0 is none: the curve's point)
        const double y = y_disc;
        const double r = std::sqrt(std::max(q(y), 0.0) * unit(rng));
        return {r * std::cos(angle), y, r * std::sin(angle)};
    }
    for (;;) {
        const double y = bottom + (top - bottom) * unit(rng);
        if (q(y) <= 0.0) continue;
        const double r = std::sqrt(q(y));
        return {r * std::cos(angle), y, r * std::sin(angle)};
    }
}

// `rays` rays aimed at random points of the quadric sor's surface from random directions, and
// rays from random points inside it: the nearest hit, its normal and every root on the line
// against the closed form. Returns how many hit.
int expect_matches_quadric(const Cubic& q, const std::vector<double>& ys, bool open, int rays, unsigned seed) {
    const Sor o = sor_of(q, ys, open);
    const double bottom = ys.front(), top = ys.back();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal;
    int hits = 0;
    for (int i = 0; i < rays; ++i) {
        const dvec3 dir = glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
        Ray ray;
        double distance = kFar;
        if (i % 4 == 3) {  // from a random point within its box
            const dvec3 lo(-o.r_max, bottom, -o.r_max), hi(o.r_max, top, o.r_max);
            ray = Ray{lo + (hi - lo) * dvec3(unit(rng), unit(rng), unit(rng)), dir};
        } else {
            distance = 0.5 + 10.0 * unit(rng);
            ray = Ray{surface_point(q, bottom, top, !open, rng) - distance * dir, dir};
        }
        const std::vector<Crossing> all = quadric_crossings(q, bottom, top, open, ray);
        const auto first = std::find_if(all.begin(), all.end(), [](const Crossing& c) { return c.t > 0.0; });
        const auto h = intersect(o, ray, 0.0, kFar);
        EXPECT_EQ(bool(h), first != all.end()) << i;
        if (distance < kFar) {
            EXPECT_TRUE(h) << i;
        }
        if (!h || first == all.end()) continue;
        ++hits;
        const double size = std::max({o.r_max, std::abs(bottom), std::abs(top)});
        EXPECT_NEAR(h->t, first->t, 1e-9 * (first->t + size)) << i;
        if (distance < kFar) {
            EXPECT_LE(h->t, distance * (1.0 + 1e-9)) << i;
        }
        EXPECT_NEAR(glm::length(h->normal), 1.0, 1e-12) << i;
        // (near a cone's apex the normal turns fast with the point: 1e-7)
        EXPECT_NEAR(glm::length(h->normal - first->normal), 0.0, 1e-7) << i;
        // The whole line.
        const std::vector<double> roots = roots_on_line(o, ray);
        EXPECT_EQ(roots.size(), all.size()) << i;
        if (roots.size() == all.size()) {
            for (std::size_t j = 0; j < roots.size(); ++j) EXPECT_NEAR(roots[j], all[j].t, 1e-9 * (std::abs(all[j].t) + size)) << i << " " << j;
        }
    }
    return hits;
}

// Unit vectors.
const dvec3 kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);

void expect_hit(const Sor& o, const Ray& ray, double t, const dvec3& normal, double t_min = 0.0) {
    const auto h = intersect(o, ray, t_min, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, t, 1e-12 * std::max(1.0, t));
    EXPECT_NEAR(glm::length(h->normal - normal), 0.0, 1e-12);
}

// ---- (1) r^2 constant: the capped cylinder.

const Cubic kCylinder{1.5 * 1.5, 0, 0, 0};  // radius 1.5
const std::vector<double> kCylinderYs{-1.0, 0.5, 2.0};

TEST(Sor, ConstantRadiusIsTheCappedCylinder) {
    const Sor o = sor_of(kCylinder, kCylinderYs);
    EXPECT_EQ(o.base_r2, 2.25);
    EXPECT_EQ(o.cap_r2, 2.25);
    expect_hit(o, {{-10, 0, 0}, kX}, 8.5, -kX);                 // the side, horizontal
    expect_hit(o, {{-10, 0, 0}, kX}, 11.5, kX, 8.5 + 1e-9);      // and out of it
    expect_hit(o, {{0.3, -5, 0.2}, kY}, 4.0, -kY);               // the base from below
    expect_hit(o, {{0.3, 6, 0.2}, -kY}, 4.0, kY);                // the cap from above
    expect_hit(o, {{0, -5, 0}, kY}, 4.0, -kY);                   // along the axis
    expect_hit(o, {{0, -5, 0}, kY}, 7.0, kY, 4.0 + 1e-9);
    expect_hit(o, {{0.2, 0.1, 0}, kX}, 1.3, kX);                 // from inside: the side
    expect_hit(o, {{0.2, 0.1, 0}, kY}, 1.9, kY);                 // the cap
    expect_hit(o, {{0.2, 0.1, 0}, -kY}, 1.1, -kY);               // the base
    expect_hit(o, {{-10, 0.5, 0}, kX}, 8.5, -kX);                // at the segments' boundary height
    expect_hit(o, {{-10, 2.0, 0}, kX}, 8.5, -kX);                // in the cap's plane: the rim
    // Diagonal: in through the side, out through the cap.
    const dvec3 dir = glm::normalize(dvec3(1, 1, 0));
    expect_hit(o, {{-3, 0, 0}, dir}, 1.5 * std::sqrt(2.0), -kX);
    expect_hit(o, {{-3, 0, 0}, dir}, 2.0 * std::sqrt(2.0), kY, 1.5 * std::sqrt(2.0) + 1e-9);
    // Misses: over it, under it, beside it, going away, beyond t_max.
    EXPECT_FALSE(intersect(o, {{-10, 2.01, 0}, kX}, 0.0, kFar));
    EXPECT_FALSE(intersect(o, {{-10, -1.01, 0}, kX}, 0.0, kFar));
    EXPECT_FALSE(intersect(o, {{1.51, -5, 0}, kY}, 0.0, kFar));
    EXPECT_FALSE(intersect(o, {{-10, 0, 0}, -kX}, 0.0, kFar));
    EXPECT_FALSE(intersect(o, {{-10, 0, 0}, kX}, 0.0, 8.49));
    // The line through both walls, at the boundary height: each wall once; up the axis, the discs.
    for (const auto& [ray, ts] : {std::pair{Ray{{-10, 0.5, 0}, kX}, std::pair{8.5, 11.5}}, std::pair{Ray{{0, -5, 0}, kY}, std::pair{4.0, 7.0}}}) {
        const std::vector<double> roots = roots_on_line(o, ray);
        ASSERT_EQ(roots.size(), 2u);
        EXPECT_NEAR(roots[0], ts.first, 1e-12);
        EXPECT_NEAR(roots[1], ts.second, 1e-12);
    }
}

TEST(Sor, GrazingTheCylinderHitsOnlyWhereItTouches) {
    const Sor o = sor_of(kCylinder, kCylinderYs);
    auto touching = intersect(o, {{-10, 0, 1.5}, kX}, 0.0, kFar);  // tangent: a hit
    ASSERT_TRUE(touching);
    EXPECT_NEAR(touching->t, 10.0, 1e-5);
    for (double delta : {1e-3, 1e-6, 1e-9}) {
        auto h = intersect(o, {{-10, 0.3, 1.5 - delta}, kX}, 0.0, kFar);
        ASSERT_TRUE(h) << delta;
        const double z = 1.5 - delta;
        EXPECT_NEAR(h->t, 10.0 - std::sqrt(2.25 - z * z), 1e-7) << delta;
        EXPECT_FALSE(intersect(o, {{-10, 0.3, 1.5 + delta}, kX}, 0.0, kFar)) << delta;
    }
    // Down along the wall (f is 0 all along the line): the base's rim first.
    auto along = intersect(o, {{1.5, 5, 0}, -kY}, 0.0, kFar);
    ASSERT_TRUE(along);
    EXPECT_NEAR(along->t, 3.0, 1e-12);
}

TEST(Sor, CylinderAgreesWithItsClosedFormForRandomRays) {
    EXPECT_GT(expect_matches_quadric(kCylinder, kCylinderYs, false, 1200, 1), 1000);
}

// ---- (2) cones (r^2 quadratic in y) and paraboloids (r^2 linear in y).

TEST(Sor, ConeIsTheConeAndItsApexIsAPoint) {
    // r = k (y + 1): the apex at y = -1.
    const double k = 0.7;
    const Cubic cone{k * k, 2.0 * k * k, k * k, 0};
    const Sor o = sor_of(cone, {-1.0, 0.0, 1.5});
    EXPECT_EQ(o.base_r2, 0.0);  // the apex: no base disc
    // Horizontally at height y: the side at radius k (y + 1), its normal (1, -k, 0) / |.|.
    const double y = 0.25, r = k * (y + 1.0);
    expect_hit(o, {{-10, y, 0}, kX}, 10.0 - r, glm::normalize(dvec3(-1, -k, 0)));
    // Up the axis: the apex (a simple root of f = -k^2 (y + 1)^2 ... a double one: touching) and the cap.
    auto apex = intersect(o, {{0, -5, 0}, kY}, 0.0, kFar);
    ASSERT_TRUE(apex);
    EXPECT_NEAR(apex->t, 4.0, 1e-5);
    const std::vector<double> axis = roots_on_line(o, {{0, -5, 0}, kY});
    ASSERT_EQ(axis.size(), 2u);
    EXPECT_NEAR(axis[0], 4.0, 1e-5);
    EXPECT_EQ(axis[1], 6.5);
    // Along a generator (f is 0 all along the line's stretch in the sor): one root there, and the cap's rim.
    const dvec3 generator = glm::normalize(dvec3(k, 1, 0));
    const std::vector<double> side = roots_on_line(o, {{0, -1, 0}, generator});
    EXPECT_LE(side.size(), 2u);
    // Random rays against the closed form, with both discs (a frustum) and with the apex.
    EXPECT_GT(expect_matches_quadric(cone, {-0.5, 0.0, 0.7, 1.5}, false, 1200, 2), 1000);
    EXPECT_GT(expect_matches_quadric(cone, {-1.0, 0.0, 1.5}, false, 1200, 3), 1000);
    // A double cone, its apex within a segment.
    EXPECT_GT(expect_matches_quadric(cone, {-2.0, 1.0}, false, 1200, 4), 1000);
}

TEST(Sor, ParaboloidIsTheParaboloid) {
    // r^2 = 2 (y - 0.5): the vertex at y = 0.5.
    const Cubic paraboloid{-1.0, 2.0, 0.0, 0.0};
    const Sor o = sor_of(paraboloid, {0.5, 1.0, 2.5});
    EXPECT_EQ(o.base_r2, 0.0);
    EXPECT_EQ(o.cap_r2, 4.0);
    // Up the axis: the vertex (a simple root at the curve's end) and the cap.
    EXPECT_EQ(roots_on_line(o, {{0, -5, 0}, kY}).size(), 2u);
    expect_hit(o, {{0, -5, 0}, kY}, 5.5, -kY);
    // Horizontally at y = 1.5: radius sqrt(2), normal (2x, -2, 2z) / |.|.
    expect_hit(o, {{-10, 1.5, 0}, kX}, 10.0 - std::sqrt(2.0), glm::normalize(dvec3(-2.0 * std::sqrt(2.0), -2, 0)));
    EXPECT_GT(expect_matches_quadric(paraboloid, {0.5, 1.0, 2.5}, false, 1200, 5), 1000);
    EXPECT_GT(expect_matches_quadric(paraboloid, {0.5, 2.5}, true, 1200, 6), 1000);
}

// ---- (3) r^2 = R^2 - y^2 over [-R, R]: the sphere.

TEST(Sor, SphereInThreeSegmentsIsTheSphere) {
    const double R = 1.3;
    const Cubic sphere{R * R, 0, -1, 0};
    const Sor o = sor_of(sphere, {-R, -0.4, 0.5, R});
    EXPECT_EQ(o.base_r2, 0.0);
    EXPECT_EQ(o.cap_r2, 0.0);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal;
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        // Aimed at random points of the sphere, a third of them on the segments' boundary circles.
        const double y = i % 3 == 0 ? (i % 2 ? -0.4 : 0.5) : R * (2.0 * unit(rng) - 1.0);
        const double angle = 2.0 * M_PI * unit(rng), r = std::sqrt(R * R - y * y);
        const dvec3 target(r * std::cos(angle), y, r * std::sin(angle));
        const dvec3 dir = glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
        const double distance = 0.5 + 10.0 * unit(rng);
        const Ray ray{target - distance * dir, dir};
        const std::optional<double> t = sphere_hit_t(dvec3(0.0), R, ray, 0.0, kFar);
        const auto h = intersect(o, ray, 0.0, kFar);
        ASSERT_TRUE(t) << i;
        ASSERT_TRUE(h) << i;
        ++hits;
        EXPECT_NEAR(h->t, *t, 1e-9 * *t) << i;
        EXPECT_NEAR(glm::length(h->normal - (ray.origin + *t * dir) / R), 0.0, 1e-9) << i;
        // Both crossings on the line, once each.
        const std::vector<double> roots = roots_on_line(o, ray);
        const std::optional<double> out = sphere_hit_t(dvec3(0.0), R, ray, *t, kFar);
        if (!out) continue;  // touching
        ASSERT_EQ(roots.size(), 2u) << i;
        EXPECT_NEAR(roots[0], *t, 1e-9 * *t) << i;
        EXPECT_NEAR(roots[1], *out, 1e-9 * *out) << i;
    }
    EXPECT_EQ(hits, 3000);
    // Through both poles along the axis, and through the segments' boundaries horizontally.
    const std::vector<double> poles = roots_on_line(o, {{0, -5, 0}, kY});
    ASSERT_EQ(poles.size(), 2u);
    EXPECT_NEAR(poles[0], 5.0 - R, 1e-9);
    EXPECT_NEAR(poles[1], 5.0 + R, 1e-9);
    expect_hit(o, {{0, 5, 0}, -kY}, 5.0 - R, kY);
    for (double y : {-0.4, 0.5}) {
        const double r = std::sqrt(R * R - y * y);
        EXPECT_EQ(roots_on_line(o, {{-10, y, 0}, kX}).size(), 2u) << y;
        const auto h = intersect(o, {{-10, y, 0}, kX}, 0.0, kFar);
        ASSERT_TRUE(h) << y;
        EXPECT_NEAR(h->t, 10.0 - r, 1e-12) << y;
        EXPECT_NEAR(glm::length(h->normal - dvec3(-r, y, 0) / R), 0.0, 1e-12) << y;
    }
}

// ---- (4) a spline that dips below r^2 = 0 within a segment: no surface there.

TEST(Sor, NoSurfaceWhereTheSplineDipsBelowZero) {
    // r^2 = -(y - 1)(y - 2)(y - 4) on [0, 3], one segment: > 0 on [0, 1) and (2, 3], < 0 between.
    const Cubic dip{8.0, -14.0, 7.0, -1.0};
    const Sor o = sor_of(dip, {0.0, 3.0});
    ASSERT_EQ(o.segments.size(), 1u);
    EXPECT_EQ(o.base_r2, 8.0);
    EXPECT_EQ(o.cap_r2, 2.0);
    // Through the gap: horizontally, slanting within it, and across the axis.
    EXPECT_FALSE(intersect(o, {{-10, 1.5, 0}, kX}, 0.0, kFar));
    EXPECT_TRUE(roots_on_line(o, {{-10, 1.5, 0}, kX}).empty());
    EXPECT_FALSE(intersect(o, {{-5, 1.2, 0.1}, glm::normalize(dvec3(1, 0.05, 0))}, 0.0, kFar));
    EXPECT_FALSE(intersect(o, {{0, 1.5, 0}, glm::normalize(dvec3(1, 0.1, 1))}, 0.0, kFar));
    EXPECT_FALSE(inside(o, {0, 1.5, 0}));
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        const double y = 1.01 + 0.98 * unit(rng), angle = 2.0 * M_PI * unit(rng);
        EXPECT_FALSE(intersect(o, {{-10 * std::cos(angle), y, -10 * std::sin(angle)}, {std::cos(angle), 0, std::sin(angle)}}, 0.0, kFar)) << i;
    }
    // Up the axis: the base, the lower part's tip at y = 1 (normal +y), the upper's at y = 2, the cap.
    const Ray axis{{0, -5, 0}, kY};
    const std::vector<double> roots = roots_on_line(o, axis);
    ASSERT_EQ(roots.size(), 4u);
    const double ys[] = {0.0, 1.0, 2.0, 3.0};
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(roots[j], ys[j] + 5.0, 1e-12) << j;
    EXPECT_TRUE(inside(o, {0, 0.5, 0}));
    EXPECT_FALSE(inside(o, {0, 1.5, 0}));
    EXPECT_TRUE(inside(o, {0, 2.5, 0}));
    expect_hit(o, {{0, 0.5, 0}, kY}, 0.5, kY);
    expect_hit(o, {{0, 1.5, 0}, kY}, 0.5, -kY);
    // Below the gap, horizontally: radius sqrt(r^2(0.5)).
    expect_hit(o, {{-10, 0.5, 0}, kX}, 10.0 - std::sqrt(dip(0.5)), glm::normalize(dvec3(-2.0 * std::sqrt(dip(0.5)), -(-14.0 + 14.0 * 0.5 - 3.0 * 0.25), 0)));
    // A hyperboloid of two sheets, r^2 = (y - 1)(y - 2) on [0, 3], against its closed form.
    EXPECT_GT(expect_matches_quadric({2.0, -3.0, 1.0, 0.0}, {0.0, 1.5, 3.0}, false, 1200, 13), 700);
}

// ---- (5) open or closed.

TEST(Sor, OpenHasNoDiscsAndShowsItsInside) {
    const Cubic unit_cylinder{1.0, 0, 0, 0};
    const Sor closed = sor_of(unit_cylinder, {0.0, 2.0}), open = sor_of(unit_cylinder, {0.0, 2.0}, true);
    // Straight down inside the wall: the cap, or nothing.
    expect_hit(closed, {{0.5, 5, 0}, -kY}, 3.0, kY);
    EXPECT_FALSE(intersect(open, {{0.5, 5, 0}, -kY}, 0.0, kFar));
    EXPECT_TRUE(roots_on_line(open, {{0, -5, 0}, kY}).empty());
    EXPECT_EQ(roots_on_line(closed, {{0, -5, 0}, kY}).size(), 2u);
    // Slanting into the top: the cap, or through the opening onto the inner wall at y = 1, its
    // normal outward (the way the ray goes).
    const dvec3 dir = glm::normalize(dvec3(0.5, -1, 0));
    expect_hit(closed, {{0, 3, 0}, dir}, std::sqrt(1.25), kY);
    expect_hit(open, {{0, 3, 0}, dir}, std::sqrt(5.0), kX);
    // From outside: the outer wall, then the inner wall's far side.
    expect_hit(open, {{-10, 1, 0}, kX}, 9.0, -kX);
    expect_hit(open, {{-10, 1, 0}, kX}, 11.0, kX, 9.0 + 1e-9);
    // Random rays against the closed form of the open cylinder.
    EXPECT_GT(expect_matches_quadric(unit_cylinder, {0.0, 0.7, 2.0}, true, 1200, 14), 700);
}

// ---- (6) every root on the line, and the inside between them, against a march.

// A vase: its r^2 a spline through knots, dipping below 0 between y = 2.4 and 2.7 (a waist that
// parts the body from the lip) and closing to a point at the bottom.
const std::vector<Knot> kVase{{0.0, 0.0, 3.0}, {0.5, 1.2, 1.0}, {1.2, 1.0, -1.5}, {2.0, 0.3, -1.0},
                              {2.55, -0.05, 0.0}, {3.0, 0.5, 2.0}, {3.3, 1.0, 0.5}};

// Inside by hand: between the ends and within the spline's radius.
bool vase_inside(const std::vector<Knot>& knots, const dvec3& p) {
    return p.y > knots.front().y && p.y < knots.back().y && p.x * p.x + p.z * p.z < spline_r2(knots, p.y);
}

// Where the line's inside changes along it in (t0, t1), by a march of `steps` samples, each
// change bisected.
std::vector<double> march(const std::vector<Knot>& knots, const Ray& ray, double t0, double t1, int steps) {
    auto in = [&](double t) { return vase_inside(knots, ray.origin + t * ray.dir); };
    std::vector<double> changes;
    bool previous = in(t0);
    for (int i = 1; i <= steps; ++i) {
        const double t = t0 + (t1 - t0) * i / steps;
        const bool now = in(t);
        if (now == previous) continue;
        double lo = t0 + (t1 - t0) * (i - 1) / steps, hi = t;
        for (int k = 0; k < 200; ++k) {
            const double mid = 0.5 * (lo + hi);
            if (!(mid > lo && mid < hi)) break;
            if (in(mid) == previous) lo = mid; else hi = mid;
        }
        changes.push_back(0.5 * (lo + hi));
        previous = now;
    }
    return changes;
}

// The line's stretch through the box [-r, r] x [y0, y1] x [-r, r], grown a little.
std::pair<double, double> through_box(const Sor& o, const Ray& ray) {
    const dvec3 lo(-o.r_max - 0.01, o.segments.front().y0 - 0.01, -o.r_max - 0.01);
    const dvec3 hi(o.r_max + 0.01, o.segments.back().y1 + 0.01, o.r_max + 0.01);
    double t0 = -kFar, t1 = kFar;
    for (int i = 0; i < 3; ++i) {
        if (ray.dir[i] == 0.0) continue;
        const double a = (lo[i] - ray.origin[i]) / ray.dir[i], b = (hi[i] - ray.origin[i]) / ray.dir[i];
        t0 = std::max(t0, std::min(a, b));
        t1 = std::min(t1, std::max(a, b));
    }
    return {t0, t1};
}

TEST(Sor, RootsOnLineAlternateInsideAndOutsideAndAgreeWithAMarch) {
    const Sor o = spline(kVase);
    ASSERT_EQ(o.segments.size(), 6u);
    EXPECT_EQ(o.base_r2, 0.0);
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal;
    int crossings = 0, vertical = 0, horizontal = 0;
    for (int i = 0; i < 600; ++i) {
        // From a point in the box (roots behind it too), any direction length; some lines
        // vertical, some horizontal at a knot's height.
        const dvec3 from(o.r_max * (2.0 * unit(rng) - 1.0), 3.3 * unit(rng), o.r_max * (2.0 * unit(rng) - 1.0));
        dvec3 dir(normal(rng), normal(rng), normal(rng));
        Ray ray{from, (0.2 + 3.0 * unit(rng)) * glm::normalize(dir)};
        if (i % 7 == 0) {
            ray.dir = dvec3(0, i % 2 ? 2.0 : -0.5, 0);
            ++vertical;
        } else if (i % 5 == 0) {
            ray.origin.y = kVase[1 + (i / 5) % 5].y;
            ray.dir.y = 0.0;
            ++horizontal;
        }
        const std::vector<double> roots = roots_on_line(o, ray);
        const auto [t0, t1] = through_box(o, ray);
        const std::vector<double> marched = march(kVase, ray, t0, t1, 20000);
        ASSERT_EQ(roots.size(), marched.size()) << i;
        ASSERT_EQ(roots.size() % 2, 0u) << i;
        crossings += int(roots.size());
        const double scale = glm::length(ray.dir);
        for (std::size_t j = 0; j < roots.size(); ++j) {
            EXPECT_NEAR(roots[j], marched[j], 1e-9 * (1.0 + std::abs(roots[j]) * scale) / scale) << i << " " << j;
            if (j > 0) {
                EXPECT_LT(roots[j - 1], roots[j]) << i;
            }
            // Between consecutive roots the side alternates, inside first.
            if (j + 1 < roots.size()) {
                EXPECT_EQ(inside(o, ray.origin + 0.5 * (roots[j] + roots[j + 1]) * ray.dir), j % 2 == 0) << i << " " << j;
            }
        }
        if (!roots.empty()) {
            EXPECT_FALSE(inside(o, ray.origin + (roots.front() - 1e-6 / scale) * ray.dir)) << i;
            EXPECT_FALSE(inside(o, ray.origin + (roots.back() + 1e-6 / scale) * ray.dir)) << i;
        }
        // The nearest hit ahead is the first root ahead, with the normal of f or of a disc.
        const auto ahead = std::upper_bound(roots.begin(), roots.end(), 0.0);
        const auto h = intersect(o, ray, 0.0, kFar);
        ASSERT_EQ(bool(h), ahead != roots.end()) << i;
        if (!h) continue;
        EXPECT_NEAR(h->t, *ahead, 1e-12 * (1.0 + std::abs(*ahead))) << i;
        const dvec3 p = ray.origin + h->t * ray.dir;
        const double e = 1e-6;
        const dvec3 gradient(2.0 * p.x, -(spline_r2(kVase, p.y + e) - spline_r2(kVase, p.y - e)) / (2.0 * e), 2.0 * p.z);
        const bool on_cap = std::abs(p.y - 3.3) < 1e-12 && std::abs(glm::dot(p, p) - p.y * p.y - 1.0) > 1e-9;
        const dvec3 expected = on_cap ? kY : glm::normalize(gradient);
        EXPECT_NEAR(glm::length(h->normal - expected), 0.0, 1e-6) << i;
    }
    EXPECT_GT(crossings, 600);
    EXPECT_GT(vertical, 50);
    EXPECT_GT(horizontal, 50);
}

// Random splines (2 to 9 knots, dipping below 0 here and there) at sizes from 0.01 to 100, a third
// of them lifted by 1000 of their size along the axis, crossed by random lines (some vertical, some
// horizontal at an inner knot's height): every root against the march, the inside alternating,
// and the nearest hit ahead the first root ahead.
TEST(Sor, RandomSplinesAtAnySizeAgreeWithAMarch) {
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal;
    int crossings = 0;
    for (int shape = 0; shape < 15; ++shape) {
        const int n = 2 + int(8 * unit(rng));
        const double S = std::pow(10.0, double(shape % 5) - 2.0), lift = shape % 3 == 0 ? 1000.0 * S : 0.0;
        std::vector<Knot> knots;
        double y = -1.0 + 2.0 * unit(rng);
        for (int i = 0; i < n; ++i) {
            knots.push_back({y * S + lift, (-0.3 + 1.8 * unit(rng)) * S * S, 3.0 * normal(rng) * S});
            y += 0.05 + unit(rng);
        }
        const Sor o = spline(knots);
        const double bottom = knots.front().y, top = knots.back().y;
        for (int i = 0; i < 150; ++i) {
            const dvec3 from(o.r_max * (2.0 * unit(rng) - 1.0), bottom + (top - bottom) * unit(rng), o.r_max * (2.0 * unit(rng) - 1.0));
            Ray ray{from, (0.2 + 3.0 * unit(rng)) * glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)))};
            if (i % 7 == 0) {
                ray.dir = dvec3(0, 1, 0);
            } else if (i % 5 == 0 && n > 2) {
                ray.origin.y = knots[1 + int(unit(rng) * (n - 2))].y;
                ray.dir.y = 0.0;
            }
            const std::vector<double> roots = roots_on_line(o, ray);
            const auto [t0, t1] = through_box(o, ray);
            const std::vector<double> marched = march(knots, ray, t0, t1, 20000);
            ASSERT_EQ(roots.size(), marched.size()) << shape << " " << i;
            crossings += int(roots.size());
            // t to 1e-9 of the size, over the direction's length.
            const double scale = glm::length(ray.dir), size = S;
            for (std::size_t j = 0; j < roots.size(); ++j) {
                EXPECT_NEAR(roots[j], marched[j], 1e-9 * size / scale) << shape << " " << i << " " << j;
                if (j + 1 < roots.size()) {
                    EXPECT_EQ(inside(o, ray.origin + 0.5 * (roots[j] + roots[j + 1]) * ray.dir), j % 2 == 0) << shape << " " << i << " " << j;
                }
            }
            const auto ahead = std::upper_bound(roots.begin(), roots.end(), 0.0);
            const auto h = intersect(o, ray, 0.0, kFar);
            ASSERT_EQ(bool(h), ahead != roots.end()) << shape << " " << i;
            if (h) {
                EXPECT_NEAR(h->t, *ahead, 1e-9 * size / scale) << shape << " " << i;
            }
        }
    }
    EXPECT_GT(crossings, 2000);
}

// ---- (7) the ray's own parameter.

TEST(Sor, DirectionLengthIsTheRaysOwnParameter) {
    const Sor o = spline(kVase);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal;
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        const dvec3 dir = glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
        const dvec3 to(o.r_max * (2.0 * unit(rng) - 1.0), 3.3 * unit(rng), o.r_max * (2.0 * unit(rng) - 1.0));
        const Ray unit_ray{to - 6.0 * dir, dir};
        const auto reference = intersect(o, unit_ray, 0.0, kFar);
        const std::vector<double> unit_line = roots_on_line(o, unit_ray);
        for (double k : {1e-3, 0.37, 7.5}) {
            const Ray ray{unit_ray.origin, k * unit_ray.dir};
            const auto h = intersect(o, ray, 0.0, kFar);
            ASSERT_EQ(bool(h), bool(reference)) << i << " " << k;
            const std::vector<double> line = roots_on_line(o, ray);
            ASSERT_EQ(line.size(), unit_line.size()) << i << " " << k;
            for (std::size_t j = 0; j < line.size(); ++j) EXPECT_NEAR(line[j] * k, unit_line[j], 1e-12 * 10.0) << i << " " << k;
            if (!h) continue;
            EXPECT_NEAR(h->t * k, reference->t, 1e-12 * reference->t) << i << " " << k;
            EXPECT_NEAR(glm::length(h->normal - reference->normal), 0.0, 1e-9) << i << " " << k;
            // t_min and t_max are the ray's own too.
            EXPECT_FALSE(intersect(o, ray, 0.0, 0.999 * reference->t / k)) << i << " " << k;
            EXPECT_TRUE(intersect(o, ray, 0.999 * reference->t / k, 1.001 * reference->t / k)) << i << " " << k;
        }
        hits += bool(reference);
    }
    EXPECT_GT(hits, 100);
}

// ---- (8) far from the origin.

TEST(Sor, FarFromTheOriginItKeepsItsPrecision) {
    const double R = 1.0;
    const Sor sphere = sor_of({R * R, 0, -1, 0}, {-R, 0.2, R});
    // From 1e5 along x: t to the ray's own rounding.
    expect_hit(sphere, {{1e5, 0.3, 0.2}, -kX}, 1e5 - std::sqrt(1.0 - 0.09 - 0.04), glm::normalize(dvec3(std::sqrt(0.87), 0.3, 0.2)));
    // From 1e5 away in random directions, aimed at random points of the sphere: the hit within
    // 1e-10 of the point (a few roundings of 1e5).
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal;
    for (int i = 0; i < 300; ++i) {
        const dvec3 target = R * glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
        dvec3 dir;
        do dir = glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
        while (glm::dot(dir, target) > -0.3 * R);  // onto the near side, not grazing it
        const Ray ray{target - 1e5 * dir, dir};
        const auto h = intersect(sphere, ray, 0.0, kFar);
        ASSERT_TRUE(h) << i;
        EXPECT_NEAR(glm::length(ray.origin + h->t * dir - target), 0.0, 1e-10) << i;
        EXPECT_NEAR(glm::length(h->normal - target / R), 0.0, 1e-9) << i;
    }
    // A thin vase (a hundredth of the size) from 1e5 away: down its axis onto the bottom's point,
    // and horizontally onto its belly.
    std::vector<Knot> small = kVase;
    for (Knot& k : small) {
        k.y *= 0.01;
        k.r2 *= 1e-4;
        k.slope *= 0.01;
    }
    const Sor thin = spline(small);
    auto up = intersect(thin, {{0, -1e5, 0}, kY}, 0.0, kFar);
    ASSERT_TRUE(up);
    EXPECT_NEAR(up->t, 1e5, 1e-10);
    const double r = std::sqrt(spline_r2(small, 0.01));
    auto side = intersect(thin, {{-1e5, 0.01, 0}, kX}, 0.0, kFar);
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->t, 1e5 - r, 1e-10);
    const double e = 1e-8, slope = (spline_r2(small, 0.01 + e) - spline_r2(small, 0.01 - e)) / (2.0 * e);
    EXPECT_NEAR(glm::length(side->normal - glm::normalize(dvec3(-2.0 * r, -slope, 0))), 0.0, 1e-6);
}

// ---- (9) texture.

TEST(Sor, TextureIsTheAngleAboutYAndTheHeight) {
    const Sor o = sor_of(kCylinder, kCylinderYs);  // y from -1 to 2
    auto uv = [&](double angle, double y) { return texture_uv(o, {1.5 * std::cos(angle), y, 1.5 * std::sin(angle)}); };
    EXPECT_NEAR(uv(0.0, -1.0).x, 0.0, 1e-15);  // +x
    EXPECT_NEAR(uv(0.0, -1.0).y, 0.0, 1e-15);  // the bottom
    EXPECT_NEAR(uv(0.5 * M_PI, 0.5).x, 0.25, 1e-15);  // +z
    EXPECT_NEAR(uv(0.5 * M_PI, 0.5).y, 0.5, 1e-15);
    EXPECT_NEAR(uv(M_PI, 2.0).x, 0.5, 1e-15);
    EXPECT_NEAR(uv(M_PI, 2.0).y, 1.0, 1e-15);  // the top
    EXPECT_NEAR(uv(-0.5 * M_PI, 1.25).x, 0.75, 1e-15);  // -z
    EXPECT_NEAR(uv(-0.5 * M_PI, 1.25).y, 0.75, 1e-15);
    EXPECT_GE(uv(-1e-17, 0.0).x, 0.0);  // just below +x: wrapped into [0, 1)
    EXPECT_LT(uv(-1e-17, 0.0).x, 1.0);
    EXPECT_EQ(uv(0.0, -1.5).y, 0.0);  // beyond the ends: clamped
    EXPECT_EQ(uv(0.0, 2.5).y, 1.0);
    EXPECT_EQ(texture_uv(o, {0, 0.5, 0}), glm::dvec2(0.0, 0.5));  // on the axis
}

}  // namespace
}  // namespace sor_test
}  // namespace lancer::cpu

// The reference's torus (host/cpu/shapes/torus.cpp), its reader's checks, its box and its
// texture mapping.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/shape_bounds.hpp"
#include "cpu/shapes/shapes.hpp"
#include "scene/animation.hpp"
#include "support/test_support.hpp"

namespace lancer::cpu {
namespace torus_test {  // its own names in the unity build
namespace {

constexpr double kFar = 1e30;

// POV-Ray's torus { 2, 0.5 }: about the origin, in the XZ plane around +y.
Torus ring(double major = 2.0, double minor = 0.5) {
    Torus o;
    o.major_radius = major;
    o.minor_radius = minor;
    return o;  // axis +y, u_axis +x, v_axis +z
}

// The torus about an arbitrary centre and axis, with axes for it as the reader makes them.
Torus tilted(const dvec3& center, const dvec3& axis, double major, double minor) {
    Torus o = ring(major, minor);
    o.center = center;
    o.axis = glm::normalize(axis);
    o.u_axis = glm::normalize(glm::cross(o.axis, std::abs(o.axis.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    o.v_axis = glm::cross(o.u_axis, o.axis);
    return o;
}

// The quartic and its gradient in world space.
double quartic(const Torus& o, const dvec3& p, dvec3* gradient = nullptr) {
    const dvec3 w = p - o.center;
    const double y = glm::dot(w, o.axis);
    const dvec3 across = w - y * o.axis;
    const double R2 = o.major_radius * o.major_radius, r2 = o.minor_radius * o.minor_radius;
    const double q = glm::dot(w, w) + R2 - r2;
    if (gradient) *gradient = 4.0 * q * w - 8.0 * R2 * across;
    return q * q - 4.0 * R2 * glm::dot(across, across);
}

// The distance from p to the torus's tube surface (the ring torus's exact distance).
double tube_distance(const Torus& o, const dvec3& p) {
    const dvec3 w = p - o.center;
    const double y = glm::dot(w, o.axis);
    const double rho = glm::length(w - y * o.axis);
    return std::hypot(rho - o.major_radius, y) - o.minor_radius;
}

TEST(Torus, HitsTheOuterEquatorHeadOn) {
    auto h = intersect(ring(), {{0, 0, -10}, {0, 0, 1}}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 7.5, 1e-12);
    EXPECT_NEAR(glm::length(h->normal - dvec3(0, 0, -1)), 0.0, 1e-12);
}

TEST(Torus, EdgeOnInItsPlaneMeetsAllFourWalls) {
    // Along the diameter: the outer wall, the hole's wall, across the hole, the far walls.
    const Ray ray{{-10, 0, 0}, {1, 0, 0}};
    const double ts[] = {7.5, 8.5, 11.5, 12.5};
    const double nx[] = {-1, 1, -1, 1};
    double from = 0.0;
    for (int i = 0; i < 4; ++i) {
        auto h = intersect(ring(), ray, from, kFar);
        ASSERT_TRUE(h) << i;
        EXPECT_NEAR(h->t, ts[i], 1e-12) << i;
        EXPECT_NEAR(glm::length(h->normal - dvec3(nx[i], 0, 0)), 0.0, 1e-12) << i;
        from = h->t + 1e-9;
    }
    EXPECT_FALSE(intersect(ring(), ray, from, kFar));
    // A chord of the plane that only crosses the tube on one side.
    auto h = intersect(ring(), {{-10, 0, 1.9}, {1, 0, 0}}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 10.0 - std::sqrt(2.5 * 2.5 - 1.9 * 1.9), 1e-12);
}

TEST(Torus, ThroughTheHoleAlongTheAxisMisses) {
    EXPECT_FALSE(intersect(ring(), {{0, 10, 0}, {0, -1, 0}}, 0.0, kFar));
    EXPECT_FALSE(intersect(ring(), {{1.49, 10, 0}, {0, -1, 0}}, 0.0, kFar));  // 0.01 inside the hole's wall
    EXPECT_FALSE(intersect(ring(), {{2.51, 10, 0}, {0, -1, 0}}, 0.0, kFar));  // beyond the rim
    auto h = intersect(ring(), {{2, 10, 0}, {0, -1, 0}}, 0.0, kFar);          // down onto the tube's top
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 9.5, 1e-12);
    EXPECT_NEAR(glm::length(h->normal - dvec3(0, 1, 0)), 0.0, 1e-12);
}

TEST(Torus, MissesAroundIt) {
    EXPECT_FALSE(intersect(ring(), {{-10, 0.51, 0}, {1, 0, 0}}, 0.0, kFar));  // over the tube
    EXPECT_FALSE(intersect(ring(), {{0, 0, -10}, {0, 0, -1}}, 0.0, kFar));    // going away
    EXPECT_FALSE(intersect(ring(), {{0, 0, -10}, {0, 0, 1}}, 0.0, 7.4));      // beyond t_max
    EXPECT_FALSE(intersect(ring(), {{-10, 3, -10}, {1, 0, 1}}, 0.0, kFar));   // over it, in its box
}

TEST(Torus, GrazingTheTubeTopHitsOnlyWhereItTouches) {
    // Rays along x at heights 0.5 - delta cross the tube's top near x = -2 by sqrt(delta).
    for (double delta : {1e-3, 1e-6, 1e-9}) {  // (1e-12 is within the quartic's rounding: either)
        auto h = intersect(ring(), {{-10, 0.5 - delta, 0}, {1, 0, 0}}, 0.0, kFar);
        ASSERT_TRUE(h) << delta;
        const double half = std::sqrt(0.25 - (0.5 - delta) * (0.5 - delta));
        EXPECT_NEAR(h->t, 8.0 - half, 1e-7) << delta;
        EXPECT_FALSE(intersect(ring(), {{-10, 0.5 + delta, 0}, {1, 0, 0}}, 0.0, kFar)) << delta;
    }
    auto touching = intersect(ring(), {{-10, 0.5, 0}, {1, 0, 0}}, 0.0, kFar);  // tangent: a hit
    ASSERT_TRUE(touching);
    EXPECT_NEAR(touching->t, 8.0, 1e-5);
    // Down the hole along its wall: x = 1.5 touches the wall at y = 0 (a double root), 1e-9
    // further out crosses it twice about y = 0, 1e-9 further in misses.
    auto inner = intersect(ring(), {{1.5, 10, 0}, {0, -1, 0}}, 0.0, kFar);
    ASSERT_TRUE(inner);
    EXPECT_NEAR(inner->t, 10.0, 1e-5);
    auto across = intersect(ring(), {{1.5 + 1e-9, 10, 0}, {0, -1, 0}}, 0.0, kFar);
    ASSERT_TRUE(across);
    EXPECT_NEAR(across->t, 10.0 - std::sqrt(1e-9), 1e-7);
    EXPECT_FALSE(intersect(ring(), {{1.5 - 1e-9, 10, 0}, {0, -1, 0}}, 0.0, kFar));
}

TEST(Torus, FromInsideTheTube) {
    auto h = intersect(ring(), {{2, 0, 0}, {1, 0, 0}}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 0.5, 1e-12);
    EXPECT_NEAR(glm::length(h->normal - dvec3(1, 0, 0)), 0.0, 1e-12);  // outward, the way the ray leaves
    h = intersect(ring(), {{2, 0, 0}, {0, 0, 1}}, 0.0, kFar);  // along the tube's circle: the tube curves away
    ASSERT_TRUE(h);
    EXPECT_NEAR(tube_distance(ring(), dvec3(2, 0, 0) + h->t * dvec3(0, 0, 1)), 0.0, 1e-12);
}

TEST(Torus, DirectionLengthIsTheRaysOwnParameter) {
    auto h = intersect(ring(), {{0, 0, -10}, {0, 0, 4}}, 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 7.5 / 4.0, 1e-12);
}

// R = 0.5, r = 1: the apple (|x| up to 1.5) and the lemon inside it (|x| up to 0.5 in its
// plane, cusps at y = +-sqrt(r^2 - R^2)); f < 0 between them.
TEST(Torus, SpindleHasItsLemonInside) {
    const Torus spindle = ring(0.5, 1.0);
    const Ray ray{{-10, 0, 0}, {1, 0, 0}};
    const double ts[] = {8.5, 9.5, 10.5, 11.5};
    const double nx[] = {-1, 1, -1, 1};  // into the lemon is out of the solid
    double from = 0.0;
    for (int i = 0; i < 4; ++i) {
        auto h = intersect(spindle, ray, from, kFar);
        ASSERT_TRUE(h) << i;
        EXPECT_NEAR(h->t, ts[i], 1e-12) << i;
        EXPECT_NEAR(glm::length(h->normal - dvec3(nx[i], 0, 0)), 0.0, 1e-12) << i;
        from = h->t + 1e-9;
    }
    // Along the axis the ray passes through both cusps, where f has double roots: touching hits.
    auto cusp = intersect(spindle, {{0, 10, 0}, {0, -1, 0}}, 0.0, kFar);
    ASSERT_TRUE(cusp);
    EXPECT_NEAR(cusp->t, 10.0 - std::sqrt(0.75), 1e-5);
}

TEST(Torus, TiltedThinTorusFarFromTheOrigin) {
    const Torus o = tilted({3e5, -2e5, 7e5}, {1, 2, -0.5}, 0.8, 0.01);
    const dvec3 target = o.center + 0.8 * o.u_axis + 0.01 * o.axis;  // the tube's top
    // Straight down the axis direction onto the tube's top from 5 away.
    auto down = intersect(o, {target + 5.0 * o.axis, -o.axis}, 0.0, kFar);
    ASSERT_TRUE(down);
    EXPECT_NEAR(down->t, 5.0, 1e-9);
    EXPECT_FALSE(intersect(o, {o.center + 5.0 * o.axis, -o.axis}, 0.0, kFar));  // through the hole
}

// Rays aimed at random points of random tori (thin, fat, spindles) from random directions: the
// nearest hit is at the target or before it, on the surface (|f| small for its gradient), and
// agrees with a dense march along the ray for the first sign change of f.
TEST(Torus, AimedRandomRaysAgreeWithTheQuarticAndAMarch) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const double major = 0.2 + 2.0 * unit(rng);
        const double minor = major * (i % 4 == 3 ? 1.0 + unit(rng) : 0.02 + 0.9 * unit(rng));
        const dvec3 axis = glm::normalize(dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
        const Torus o = tilted(dvec3(unit(rng), unit(rng), unit(rng)) * 4.0 - 2.0, axis, major, minor);
        const double theta = 2.0 * M_PI * unit(rng), phi = 2.0 * M_PI * unit(rng);
        const dvec3 radial = std::cos(theta) * o.u_axis + std::sin(theta) * o.v_axis;
        // A point of the tube's circle swept about the axis: of the surface f = 0 (for a spindle,
        // where R + r cos(phi) < 0, a point of its lemon).
        const dvec3 target = o.center + major * radial + minor * (std::cos(phi) * radial + std::sin(phi) * o.axis);
        const dvec3 dir = glm::normalize(dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
        const double distance = 0.5 + 10.0 * unit(rng);
        const Ray ray{target - distance * dir, dir};
        auto h = intersect(o, ray, 0.0, kFar);
        const double size = major + minor;
        ASSERT_TRUE(h) << i;
        EXPECT_LE(h->t, distance + 1e-9 * size) << i;
        const dvec3 p = ray.origin + h->t * dir;
        dvec3 grad;
        const double f = quartic(o, p, &grad);
        if (glm::length(grad) > 1e-3 * size * size * size) {
            EXPECT_LE(std::abs(f) / glm::length(grad), 1e-12 * (size + distance)) << i;
            EXPECT_NEAR(std::abs(glm::dot(h->normal, glm::normalize(grad))), 1.0, 1e-9) << i;
            EXPECT_GE(glm::dot(h->normal, grad), 0.0) << i;
        }
        // The march: f's sign at 20,000 steps to just beyond the target; the first change
        // brackets the hit (a ray that only touches the surface there changes no sign: skipped).
        const int steps = 20000;
        const double step = distance * 1.01 / steps;
        double previous = quartic(o, ray.origin);
        for (int k = 1; k <= steps; ++k) {
            const double s = k * step;
            const double value = quartic(o, ray.origin + s * dir);
            if ((value > 0.0) != (previous > 0.0)) {
                EXPECT_LE(h->t, s + 1e-12 * size) << i;
                EXPECT_GE(h->t, s - step - 1e-12 * size) << i;
                ++hits;
                break;
            }
            previous = value;
        }
    }
    EXPECT_GT(hits, 1990);
}

TEST(Torus, TextureIsTheAnglesAboutTheAxisAndAroundTheTube) {
    const Torus o = ring();  // u axis +x, v axis +z
    auto uv = [&](double theta, double phi) {
        const dvec3 radial(std::cos(theta), 0, std::sin(theta));
        return texture_uv(o, 2.0 * radial + 0.5 * (std::cos(phi) * radial + dvec3(0, std::sin(phi), 0)));
    };
    EXPECT_NEAR(uv(0.0, 0.0).x, 0.0, 1e-15);
    EXPECT_NEAR(uv(0.0, 0.0).y, 0.0, 1e-15);  // the outer equator along +x
    EXPECT_NEAR(uv(0.5 * M_PI, 0.5 * M_PI).x, 0.25, 1e-15);  // +z
    EXPECT_NEAR(uv(0.5 * M_PI, 0.5 * M_PI).y, 0.25, 1e-15);  // the tube's top
    EXPECT_NEAR(uv(M_PI, M_PI).y, 0.5, 1e-15);               // the hole's wall
    EXPECT_NEAR(uv(-0.5 * M_PI, -0.5 * M_PI).x, 0.75, 1e-15);
    EXPECT_NEAR(uv(-0.5 * M_PI, -0.5 * M_PI).y, 0.75, 1e-15);
    EXPECT_GE(uv(-1e-17, -1e-17).x, 0.0);
    EXPECT_LT(uv(-1e-17, -1e-17).y, 1.0);
}

TEST(Torus, BoxHoldsTheTubeAndMovesWithIt) {
    Torus o = tilted({1, -2, 0.5}, {1, 1, 0}, 2.0, 0.5);
    auto box = shape_bounds(o);
    ASSERT_TRUE(box);
    EXPECT_NEAR(box->hi.x - o.center.x, 2.0 * std::sqrt(0.5) + 0.5, 1e-12);
    EXPECT_NEAR(box->hi.z - o.center.z, 2.5, 1e-12);
    EXPECT_GE(box->hi.z - o.center.z, 2.5);
    EXPECT_NEAR(o.center.y - box->lo.y, 2.0 * std::sqrt(0.5) + 0.5, 1e-12);
    // Every point of the surface is inside it.
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
            const double theta = 2.0 * M_PI * i / 64, phi = 2.0 * M_PI * j / 64;
            const dvec3 radial = std::cos(theta) * o.u_axis + std::sin(theta) * o.v_axis;
            const dvec3 p = o.center + 2.0 * radial + 0.5 * (std::cos(phi) * radial + std::sin(phi) * o.axis);
            for (int k = 0; k < 3; ++k) {
                EXPECT_LE(p[k], box->hi[k]);
                EXPECT_GE(p[k], box->lo[k]);
            }
        }
    Shape moved = o;
    translate(moved, {1, 2, 3});
    EXPECT_EQ(std::get<Torus>(moved).center, o.center + dvec3(1, 2, 3));
}

// The reader: POV-Ray's torus { major, minor } about +y at the origin by default.
const std::string kHead = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n[[object]]\ntype = \"torus\"\n";

TEST(TorusReader, ReadsPovRaysParameters) {
    Scene s = test::scene_from_text(kHead + "major_radius = 2\nminor_radius = 0.5\n");
    const Torus& o = std::get<Torus>(s.objects.at(0).shape);
    EXPECT_EQ(o.center, dvec3(0, 0, 0));
    EXPECT_EQ(o.axis, dvec3(0, 1, 0));
    EXPECT_EQ(o.major_radius, 2.0);
    EXPECT_EQ(o.minor_radius, 0.5);
    EXPECT_EQ(o.u_axis, dvec3(1, 0, 0));
    EXPECT_EQ(o.v_axis, dvec3(0, 0, 1));
    s = test::scene_from_text(kHead + "center = [1, 2, 3]\naxis = [0, 0, -2]\nmajor_radius = 1\nminor_radius = 1.5\n");
    const Torus& spindle = std::get<Torus>(s.objects.at(0).shape);
    EXPECT_EQ(spindle.center, dvec3(1, 2, 3));
    EXPECT_EQ(spindle.axis, dvec3(0, 0, -1));
    EXPECT_EQ(spindle.minor_radius, 1.5);  // a spindle torus is allowed
    EXPECT_NEAR(glm::dot(spindle.u_axis, spindle.axis), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(glm::cross(spindle.u_axis, spindle.axis) - spindle.v_axis), 0.0, 1e-15);
}

void expect_refused(const std::string& keys, int line, int column, const std::string& message) { test::expect_scene_error(kHead + keys, line, column, message); }

TEST(TorusReader, RefusesDegenerateTori) {
    expect_refused("major_radius = 0\nminor_radius = 0.5\n", 6, 16, "torus major_radius must be positive");
    expect_refused("major_radius = -1\nminor_radius = 0.5\n", 6, 16, "torus major_radius must be positive");
    expect_refused("major_radius = 1\nminor_radius = 0\n", 7, 16, "torus minor_radius must be positive");
    expect_refused("major_radius = 1\nminor_radius = -0.5\n", 7, 16, "torus minor_radius must be positive");
    expect_refused("axis = [0, 0, 0]\nmajor_radius = 1\nminor_radius = 0.5\n", 6, 8, "torus axis must not be the zero vector");
    expect_refused("major_radius = 1e-7\nminor_radius = 1\n", 7, 16, "more than 10^6 apart");
    expect_refused("center = [0, nan, 0]\nmajor_radius = 1\nminor_radius = 0.5\n", 6, 14, "finite");
    expect_refused("major_radius = inf\nminor_radius = 0.5\n", 6, 16, "finite");
    expect_refused("minor_radius = 0.5\n", 4, 1, "major_radius");  // at its [[object]]
    expect_refused("major_radius = 1\n", 4, 1, "minor_radius");
}

}  // namespace
}  // namespace torus_test
}  // namespace lancer::cpu

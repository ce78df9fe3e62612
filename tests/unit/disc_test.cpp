// The reference's disc (host/cpu/shapes/disc.cpp), its reader's checks and its texture mapping.
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
namespace {

constexpr double kFar = 1e30;

// Radius 2 about (1, 0.5, -1), across +y, with a hole of radius 0.5.
Disc annulus() {
    Disc d;
    d.center = {1, 0.5, -1};
    d.normal = {0, 1, 0};
    d.radius = 2.0;
    d.hole_radius = 0.5;
    return d;  // u_axis +x, v_axis +z: the plane's texture axes for a floor
}

Ray down_at(const dvec3& p) { return {p + dvec3(0, 3, 0), {0, -1, 0}}; }

TEST(Disc, HitsBetweenTheHoleAndTheRim) {
    auto h = intersect(annulus(), down_at({2, 0.5, -1}), 0.0, kFar);
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 3.0);
    EXPECT_EQ(h->normal, dvec3(0, 1, 0));
}

TEST(Disc, MissesBeyondTheRimAndInTheHole) {
    Disc d = annulus();
    EXPECT_FALSE(intersect(d, down_at({3.01, 0.5, -1}), 0.0, kFar));  // r = 2.01
    EXPECT_FALSE(intersect(d, down_at({1 + 1.5, 0.5, -1 + 1.5}), 0.0, kFar));  // r = 2.12, inside its box
    EXPECT_FALSE(intersect(d, down_at({1, 0.5, -1}), 0.0, kFar));  // the centre
    EXPECT_FALSE(intersect(d, down_at({1.3, 0.5, -0.7}), 0.0, kFar));  // r = 0.42
}

TEST(Disc, RimAndHoleEdgeBelongToIt) {
    Disc d = annulus();
    EXPECT_TRUE(intersect(d, down_at({3, 0.5, -1}), 0.0, kFar));    // r = 2 exactly
    EXPECT_TRUE(intersect(d, down_at({1, 0.5, -1.5}), 0.0, kFar));  // r = 0.5 exactly
}

TEST(Disc, WithoutAHoleItsCentreIsOnIt) {
    Disc d = annulus();
    d.hole_radius = 0.0;
    EXPECT_TRUE(intersect(d, down_at({1, 0.5, -1}), 0.0, kFar));
}

TEST(Disc, HitFromEitherSideWithTheSameNormal) {
    Disc d = annulus();
    auto above = intersect(d, {{2, 4, -1}, {0, -1, 0}}, 0.0, kFar);
    auto below = intersect(d, {{2, -4, -1}, {0, 1, 0}}, 0.0, kFar);
    ASSERT_TRUE(above && below);
    EXPECT_DOUBLE_EQ(above->t, 3.5);
    EXPECT_DOUBLE_EQ(below->t, 4.5);
    EXPECT_EQ(above->normal, below->normal);  // the geometric normal; the tracer turns it
}

TEST(Disc, ParallelAndRecedingRaysMiss) {
    Disc d = annulus();
    EXPECT_FALSE(intersect(d, {{-3, 0.5, -1}, {1, 0, 0}}, 0.0, kFar));  // in its plane
    EXPECT_FALSE(intersect(d, {{2, 1.5, -1}, {0, 1, 0}}, 0.0, kFar));   // going away
    EXPECT_FALSE(intersect(d, down_at({2, 0.5, -1}), 0.0, 2.9));        // beyond t_max
    EXPECT_FALSE(intersect(d, down_at({2, 0.5, -1}), 3.1, kFar));       // before t_min
}

TEST(Disc, GrazingRaysHitWithinTheRimOnly) {
    Disc d = annulus();
    for (double c : {1e-3, 1e-6, 1e-9}) {
        dvec3 dir = glm::normalize(dvec3(1, -c, 0.3));
        dvec3 target(2.2, 0.5, -0.6);  // r = 1.26
        auto h = intersect(d, {target - 10.0 * dir, dir}, 0.0, kFar);
        ASSERT_TRUE(h) << c;
        EXPECT_NEAR(h->t, 10.0, 1e-9 / c) << c;
        dvec3 beyond(3.5, 0.5, -1);  // r = 2.5
        EXPECT_FALSE(intersect(d, {beyond - 10.0 * dir, dir}, 0.0, kFar)) << c;
    }
}

TEST(Disc, TiltedDiscFarFromTheOrigin) {
    Disc d;
    d.center = {3e5, -2e5, 7e5};
    d.normal = glm::normalize(dvec3(1, 2, -0.5));
    d.radius = 0.25;
    dvec3 along = glm::normalize(glm::cross(d.normal, dvec3(0, 0, 1)));
    dvec3 dir = glm::normalize(dvec3(-0.3, -1, 0.2));
    auto in = intersect(d, {d.center + 0.24 * along - 5.0 * dir, dir}, 0.0, kFar);
    ASSERT_TRUE(in);
    EXPECT_NEAR(in->t, 5.0, 1e-9);
    EXPECT_FALSE(intersect(d, {d.center + 0.26 * along - 5.0 * dir, dir}, 0.0, kFar));
}

// Rays aimed at random points of a tilted annulus from random directions hit them (nothing else
// is in the way of a flat disc); rays aimed into its hole or beyond its rim miss; a ray leaving
// a hit to either side never meets it again.
TEST(Disc, AimedRandomRaysHitTheirTargetAndLeavingRaysEscape) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Disc d;
    d.center = {0.3, -0.2, 0.7};
    d.normal = glm::normalize(dvec3(0.3, 1, -0.4));
    d.radius = 1.7;
    d.hole_radius = 0.6;
    const dvec3 a = glm::normalize(glm::cross(d.normal, dvec3(1, 0, 0)));
    const dvec3 b = glm::cross(d.normal, a);
    for (int i = 0; i < 3000; ++i) {
        double angle = M_PI * u(rng), fraction = 0.5 + 0.5 * u(rng);
        double r = i % 3 == 0 ? d.hole_radius * fraction * 0.999            // in the hole
                   : i % 3 == 1 ? d.radius * (1.001 + fraction)             // beyond the rim
                                : d.hole_radius + (d.radius - d.hole_radius) * fraction;
        dvec3 target = d.center + r * (std::cos(angle) * a + std::sin(angle) * b);
        dvec3 dir = glm::normalize(dvec3(u(rng), u(rng), u(rng)));
        if (std::abs(glm::dot(dir, d.normal)) < 1e-3) continue;
        double distance = 0.01 + 10.0 * std::abs(u(rng));
        auto h = intersect(d, {target - distance * dir, dir}, 0.0, kFar);
        if (i % 3 != 2) {
            EXPECT_FALSE(h) << i << " r " << r;
            continue;
        }
        ASSERT_TRUE(h) << i;
        EXPECT_NEAR(h->t, distance, 1e-12 * (1.0 + distance) / std::abs(glm::dot(dir, d.normal))) << i;
        for (double side : {1.0, -1.0}) {
            dvec3 n = side * d.normal;
            dvec3 out = glm::normalize(n + 0.9 * dvec3(u(rng), u(rng), u(rng)));
            if (glm::dot(out, n) <= 0.05) continue;
            Ray leaving{target + ray_offset(target, dvec3(0.0)) * n, out};
            EXPECT_FALSE(intersect(d, leaving, 0.0, kFar)) << i;
        }
    }
}

TEST(Disc, TextureIsPolarFromThePlanesAxes) {
    Disc d = annulus();  // u axis +x, v axis +z
    auto uv = [&](double angle, double r) {
        return texture_uv(d, d.center + r * (std::cos(angle) * d.u_axis + std::sin(angle) * d.v_axis));
    };
    EXPECT_NEAR(uv(0.0, 0.5).x, 0.0, 1e-15);
    EXPECT_NEAR(uv(0.0, 0.5).y, 0.0, 1e-15);  // the hole's edge
    EXPECT_NEAR(uv(0.5 * M_PI, 2.0).x, 0.25, 1e-15);
    EXPECT_NEAR(uv(0.5 * M_PI, 2.0).y, 1.0, 1e-15);  // the rim
    EXPECT_NEAR(uv(-0.5 * M_PI, 1.25).x, 0.75, 1e-15);
    EXPECT_NEAR(uv(-0.5 * M_PI, 1.25).y, 0.5, 1e-15);
    EXPECT_GE(uv(-1e-17, 1.0).x, 0.0);
    EXPECT_LT(uv(-1e-17, 1.0).x, 1.0);
}

TEST(Disc, BoxHoldsTheRimAndMovesWithIt) {
    Disc d = annulus();
    d.normal = glm::normalize(dvec3(1, 1, 0));
    auto box = shape_bounds(d);
    ASSERT_TRUE(box);
    EXPECT_NEAR(box->hi.x - d.center.x, 2.0 * std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(box->hi.z - d.center.z, 2.0, 1e-12);
    EXPECT_GE(box->hi.z - d.center.z, 2.0);
    Shape moved = d;
    translate(moved, {1, 2, 3});
    EXPECT_EQ(std::get<Disc>(moved).center, d.center + dvec3(1, 2, 3));
}

// The reader: POV-Ray's names, hole_radius 0 by default, the axes of the plane's texture.
const std::string kHead = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n[[object]]\ntype = \"disc\"\n";

TEST(DiscReader, ReadsPovRaysParameters) {
    Scene s = test::scene_from_text(kHead + "center = [1, 2, 3]\nnormal = [0, 0, -2]\nradius = 1.5\n");
    const Disc& d = std::get<Disc>(s.objects.at(0).shape);
    EXPECT_EQ(d.center, dvec3(1, 2, 3));
    EXPECT_EQ(d.normal, dvec3(0, 0, -1));
    EXPECT_EQ(d.radius, 1.5);
    EXPECT_EQ(d.hole_radius, 0.0);
    EXPECT_NEAR(glm::dot(d.u_axis, d.normal), 0.0, 1e-15);
    EXPECT_NEAR(glm::dot(d.v_axis, d.normal), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(glm::cross(d.u_axis, d.v_axis) + d.normal), 0.0, 1e-15);  // u x v = -n, as the plane's
    s = test::scene_from_text(kHead + "center = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = 2\nhole_radius = 0.5\n");
    EXPECT_EQ(std::get<Disc>(s.objects.at(0).shape).hole_radius, 0.5);
}

// Each bad value fails at its key's line and column (line 6 is the first key after the head); a
// missing key fails at the [[object]] line.
void expect_refused(const std::string& keys, int line, int column, const std::string& message) { test::expect_scene_error(kHead + keys, line, column, message); }

TEST(DiscReader, RefusesDegenerateDiscs) {
    expect_refused("center = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = 0\n", 8, 10, "disc radius must be positive");
    expect_refused("center = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = -1\n", 8, 10, "disc radius must be positive");
    expect_refused("center = [0, 0, 0]\nnormal = [0, 0, 0]\nradius = 1\n", 7, 10, "disc normal must not be the zero vector");
    expect_refused("center = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = 1\nhole_radius = 1\n", 9, 15, "must be less than its radius");
    expect_refused("center = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = 1\nhole_radius = 2\n", 9, 15, "must be less than its radius");
    expect_refused("center = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = 1\nhole_radius = -0.5\n", 9, 15, "must not be negative");
    expect_refused("center = [0, nan, 0]\nnormal = [0, 1, 0]\nradius = 1\n", 6, 14, "finite");
    expect_refused("center = [0, 0, 0]\nnormal = [0, 1, 0]\nradius = inf\n", 8, 10, "finite");
    expect_refused("center = [0, 0, 0]\nnormal = [0, 1, 0]\n", 4, 1, "radius");  // at its [[object]]
}

}  // namespace
}  // namespace lancer::cpu

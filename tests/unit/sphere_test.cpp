#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

const Sphere kUnit{{0.0, 0.0, 0.0}, 1.0};

TEST(Sphere, HitsFromOutsideAtTheNearSide) {
    auto h = intersect(kUnit, {{0, 0, -5}, {0, 0, 1}}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 4.0);
    EXPECT_EQ(h->normal, dvec3(0, 0, -1));
}

TEST(Sphere, MissesWhenTheRayPassesBeside) {
    EXPECT_FALSE(intersect(kUnit, {{0, 1.0001, -5}, {0, 0, 1}}, 0.0, 1e30));
    EXPECT_FALSE(intersect(kUnit, {{0, 0, -5}, {0, 0, -1}}, 0.0, 1e30));  // pointing away
}

TEST(Sphere, GrazingRayTouchesAtOnePoint) {
    auto h = intersect(kUnit, {{0, 1, -5}, {0, 0, 1}}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0, 1e-12);
}

TEST(Sphere, FromInsideHitsTheFarSide) {
    auto h = intersect(kUnit, {{0, 0, 0.5}, {0, 0, 1}}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 0.5);
    EXPECT_EQ(h->normal, dvec3(0, 0, 1));
}

TEST(Sphere, RespectsTheInterval) {
    EXPECT_FALSE(intersect(kUnit, {{0, 0, -5}, {0, 0, 1}}, 0.0, 3.9));
    auto far = intersect(kUnit, {{0, 0, -5}, {0, 0, 1}}, 4.5, 1e30);
    ASSERT_TRUE(far);
    EXPECT_DOUBLE_EQ(far->t, 6.0);
}

TEST(Sphere, DistantSphereKeepsPrecision) {
    Sphere far{{0, 0, 1e6}, 1.0};
    auto h = intersect(far, {{0, 0, 0}, {0, 0, 1}}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 1e6 - 1.0, 1e-6);
}

// Property tests (pbrt's Reintersect): rays aimed at random surface points hit them at t = 1
// (after scaling), and a ray leaving the surface outward never hits the sphere again.
TEST(Sphere, AimedRaysHitTheirTargetAndLeavingRaysEscape) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Sphere s{{0.3, -0.2, 0.7}, 1.7};
    for (int i = 0; i < 2000; ++i) {
        dvec3 dir_on_sphere = glm::normalize(dvec3(u(rng), u(rng), u(rng)));
        dvec3 target = s.center + s.radius * dir_on_sphere;
        dvec3 origin = s.center + (s.radius + 1.0 + 5.0 * std::abs(u(rng))) * glm::normalize(dvec3(u(rng), u(rng), u(rng)));
        dvec3 d = target - origin;
        double len = glm::length(d);
        auto h = intersect(s, {origin, d / len}, 0.0, 1e30);
        ASSERT_TRUE(h) << i;
        // The aimed point is the first hit unless the sphere's near side is in the way.
        EXPECT_LE(h->t, len * (1 + 1e-12)) << i;
        dvec3 n = dir_on_sphere;
        dvec3 out = glm::normalize(n + 0.9 * dvec3(u(rng), u(rng), u(rng)) * 0.5);
        if (glm::dot(out, n) <= 0.05) continue;
        Ray leaving{target + ray_offset(target, dvec3(0.0)) * n, out};
        EXPECT_FALSE(intersect(s, leaving, 0.0, 1e30)) << i;
    }
}

}  // namespace
}  // namespace lancer::cpu

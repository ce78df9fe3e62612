#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

const Plane kFloor{{0, 0, 0}, {0, 1, 0}};

TEST(Plane, HitsFromAboveAndBelow) {
    auto h = intersect(kFloor, {{0, 2, 0}, {0, -1, 0}}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 2.0);
    EXPECT_EQ(h->normal, dvec3(0, 1, 0));
    auto below = intersect(kFloor, {{0, -3, 0}, {0, 1, 0}}, 0.0, 1e30);
    ASSERT_TRUE(below);
    EXPECT_DOUBLE_EQ(below->t, 3.0);
}

TEST(Plane, ParallelAndReceedingRaysMiss) {
    EXPECT_FALSE(intersect(kFloor, {{0, 1, 0}, {1, 0, 0}}, 0.0, 1e30));
    EXPECT_FALSE(intersect(kFloor, {{0, 0, 0}, {1, 0, 0}}, 0.0, 1e30));  // lying in the plane
    EXPECT_FALSE(intersect(kFloor, {{0, 1, 0}, {0, 1, 0}}, 0.0, 1e30));
}

TEST(Plane, GrazingRayHitsFarAway) {
    dvec3 d = glm::normalize(dvec3(1, -1e-6, 0));
    auto h = intersect(kFloor, {{0, 1, 0}, d}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR((dvec3(0, 1, 0) + h->t * d).y, 0.0, 1e-9);
}

// A shadow ray leaving an inclined plane from any hit never re-hits it (no acne).
TEST(Plane, LeavingRaysDoNotReintersect) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Plane p{{1, 2, 3}, glm::normalize(dvec3(0.3, 1, -0.2))};
    for (int i = 0; i < 2000; ++i) {
        dvec3 origin = p.point + 20.0 * dvec3(u(rng), u(rng), u(rng)) + 30.0 * p.normal;
        dvec3 d = glm::normalize(dvec3(u(rng), -1.0, u(rng)));
        auto h = intersect(p, {origin, d}, 0.0, 1e30);
        if (!h) continue;
        dvec3 hit = origin + h->t * d;
        dvec3 out = glm::normalize(p.normal + 0.5 * dvec3(u(rng), u(rng), u(rng)));
        if (glm::dot(out, p.normal) <= 0.0) continue;
        EXPECT_FALSE(intersect(p, {hit + ray_offset(hit, dvec3(0.0)) * p.normal, out}, 0.0, 1e30)) << i;
    }
}

}  // namespace
}  // namespace lancer::cpu

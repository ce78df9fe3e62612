#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

const Box kBox{{-1, 0, -1}, {1, 2, 1}};

TEST(Box, HitsTheNearFaceWithItsNormal) {
    auto h = intersect(kBox, {{0, 1, -5}, {0, 0, 1}}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 4.0);
    EXPECT_EQ(h->normal, dvec3(0, 0, -1));
    EXPECT_EQ(intersect(kBox, {{0.2, 5, 0.3}, {0, -1, 0}}, 0.0, 1e30)->normal, dvec3(0, 1, 0));
    EXPECT_EQ(intersect(kBox, {{5, 0.5, 0.3}, {-1, 0, 0}}, 0.0, 1e30)->normal, dvec3(1, 0, 0));
}

TEST(Box, Misses) {
    EXPECT_FALSE(intersect(kBox, {{0, 2.5, -5}, {0, 0, 1}}, 0.0, 1e30));
    EXPECT_FALSE(intersect(kBox, {{0, 1, -5}, {0, 0, -1}}, 0.0, 1e30));
    EXPECT_FALSE(intersect(kBox, {{3, 1, -5}, glm::normalize(dvec3(0.1, 0, 1))}, 0.0, 1e30));
}

TEST(Box, GrazingAlongAFaceCountsAsAHit) {
    // A ray in the plane of the top face, parallel to it: touches the closed box.
    EXPECT_TRUE(intersect(kBox, {{0, 2, -5}, {0, 0, 1}}, 0.0, 1e30));
}

TEST(Box, FromInsideHitsTheExitFace) {
    auto h = intersect(kBox, {{0, 1, 0}, {1, 0, 0}}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 1.0);
    EXPECT_EQ(h->normal, dvec3(1, 0, 0));
}

TEST(Box, DiagonalThroughAnEdge) {
    auto h = intersect(kBox, {{-3, 1, -3}, glm::normalize(dvec3(1, 0, 1))}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 2.0 * std::sqrt(2.0), 1e-12);
}

}  // namespace
}  // namespace lancer::cpu

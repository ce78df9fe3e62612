#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

const Box kBox{{-1, 0, -1}, {1, 2, 1}};

TEST(Box, HitsTheNearFaceWithItsNormal) {
    auto t = intersect(kBox, {{0, 1, -5}, {0, 0, 1}}, 0.0, 1e30);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(*t, 4.0);
    EXPECT_EQ(normal(kBox, {0, 1, -1}), dvec3(0, 0, -1));
    EXPECT_EQ(normal(kBox, {0.2, 2, 0.3}), dvec3(0, 1, 0));
    EXPECT_EQ(normal(kBox, {1, 0.5, 0.3}), dvec3(1, 0, 0));
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
    auto t = intersect(kBox, {{0, 1, 0}, {1, 0, 0}}, 0.0, 1e30);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(*t, 1.0);
}

TEST(Box, DiagonalThroughAnEdge) {
    auto t = intersect(kBox, {{-3, 1, -3}, glm::normalize(dvec3(1, 0, 1))}, 0.0, 1e30);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 2.0 * std::sqrt(2.0), 1e-12);
}

}  // namespace
}  // namespace lancer::cpu

#include <gtest/gtest.h>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

// The unit square in the y = 0 plane, x and z in [0, 2] x [0, 1].
const Rectangle kRect{{0, 0, 0}, {2, 0, 0}, {0, 0, 1}};

TEST(Rectangle, HitsInside) {
    auto h = intersect(kRect, {{1, 3, 0.5}, {0, -1, 0}}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 3.0);
    EXPECT_DOUBLE_EQ(h->uv.x, 0.5);  // parallelogram coordinates
    EXPECT_DOUBLE_EQ(h->uv.y, 0.5);
}

TEST(Rectangle, MissesOutsideItsEdges) {
    EXPECT_FALSE(intersect(kRect, {{2.01, 3, 0.5}, {0, -1, 0}}, 0.0, 1e30));
    EXPECT_FALSE(intersect(kRect, {{1, 3, -0.01}, {0, -1, 0}}, 0.0, 1e30));
    EXPECT_FALSE(intersect(kRect, {{-0.01, 3, 0.5}, {0, -1, 0}}, 0.0, 1e30));
    EXPECT_FALSE(intersect(kRect, {{1, 3, 1.01}, {0, -1, 0}}, 0.0, 1e30));
}

TEST(Rectangle, EdgesAndCornersAreInside) {
    EXPECT_TRUE(intersect(kRect, {{0, 1, 0}, {0, -1, 0}}, 0.0, 1e30));
    EXPECT_TRUE(intersect(kRect, {{2, 1, 1}, {0, -1, 0}}, 0.0, 1e30));
}

TEST(Rectangle, ParallelogramUsesItsOwnEdges) {
    Rectangle skew{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}};  // sheared: (1.5, 0.5) inside, (0.2, 0.8) not
    EXPECT_TRUE(intersect(skew, {{1.5, 1, 0.5}, {0, -1, 0}}, 0.0, 1e30));
    EXPECT_FALSE(intersect(skew, {{0.2, 1, 0.8}, {0, -1, 0}}, 0.0, 1e30));
}

TEST(Rectangle, ParallelRayMisses) { EXPECT_FALSE(intersect(kRect, {{-1, 0, 0.5}, {1, 0, 0}}, 0.0, 1e30)); }

TEST(Rectangle, NormalIsEdgeUCrossEdgeV) {
    dvec3 n = intersect(kRect, {{1, 3, 0.5}, {0, -1, 0}}, 0.0, 1e30)->normal;
    EXPECT_NEAR(n.x, 0.0, 1e-15);
    EXPECT_NEAR(n.y, -1.0, 1e-15);  // (2,0,0) x (0,0,1) = (0,-2,0)
    EXPECT_NEAR(n.z, 0.0, 1e-15);
}

}  // namespace
}  // namespace lancer::cpu

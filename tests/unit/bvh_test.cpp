// Property tests of the BVH builder: every primitive is in exactly one leaf, every node's box
// contains its children's (and its primitives'), and the tree is shallow enough for the GPU's
// traversal stack.
#include <random>

#include <gtest/gtest.h>

#include "accel/bvh.hpp"

namespace lancer {
namespace {

std::vector<Aabb> random_boxes(std::size_t n, unsigned seed, bool clustered) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-100.0, 100.0), size(0.01, 3.0);
    std::vector<Aabb> boxes;
    for (std::size_t i = 0; i < n; ++i) {
        glm::dvec3 c(pos(rng), pos(rng), pos(rng));
        if (clustered) c = glm::dvec3(0.0) + 1e-3 * c;  // many near-coincident centroids
        glm::dvec3 h(size(rng), size(rng), size(rng));
        boxes.push_back({c - h, c + h});
    }
    return boxes;
}

int depth_of(const Bvh& bvh, std::uint32_t node) {
    const BvhNode& n = bvh.nodes[node];
    if (n.leaf()) return 1;
    return 1 + std::max(depth_of(bvh, n.first), depth_of(bvh, n.first + 1));
}

void check(const std::vector<Aabb>& boxes, const BvhOptions& options = {}) {
    Bvh bvh = build_bvh(boxes, options);
    ASSERT_FALSE(bvh.nodes.empty());
    std::vector<int> seen(boxes.size(), 0);
    std::size_t covered = 0;
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        const BvhNode& n = bvh.nodes[i];
        if (n.leaf()) {
            EXPECT_LE(n.count, std::max<std::uint32_t>(options.max_leaf_size, 1));
            for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
                ++seen[bvh.order[k]];
                EXPECT_TRUE(n.box.contains(boxes[bvh.order[k]])) << "leaf " << i;
            }
            covered += n.count;
        } else {
            ASSERT_LT(n.first + 1, bvh.nodes.size());
            EXPECT_TRUE(n.box.contains(bvh.nodes[n.first].box)) << "node " << i;
            EXPECT_TRUE(n.box.contains(bvh.nodes[n.first + 1].box)) << "node " << i;
        }
    }
    EXPECT_EQ(covered, boxes.size());
    for (std::size_t p = 0; p < seen.size(); ++p) EXPECT_EQ(seen[p], 1) << "primitive " << p;
    EXPECT_LE(depth_of(bvh, 0), 60);
}

TEST(Bvh, EveryPrimitiveInExactlyOneLeafAndBoxesNest) {
    check(random_boxes(1000, 1, false));
    check(random_boxes(37, 2, false));
    check(random_boxes(1, 3, false));
}

TEST(Bvh, CoincidentCentroidsStillSplitAndStayShallow) {
    check(random_boxes(500, 4, true));
    std::vector<Aabb> same(300, Aabb{glm::dvec3(0.0), glm::dvec3(1.0)});
    check(same);
}

TEST(Bvh, DegenerateLineOfBoxesKeepsDepthBounded) {
    // Exponentially spaced boxes are the classic worst case for SAH depth.
    std::vector<Aabb> boxes;
    for (int i = 0; i < 2000; ++i) {
        double x = std::pow(1.01, i);
        boxes.push_back({glm::dvec3(x, 0, 0), glm::dvec3(x + 1e-3, 1, 1)});
    }
    check(boxes);
}

// Enough boxes for the right subtree to be built on a thread of its own, its nodes then drained
// into the tree's (core/page_release.hpp): the tree still nests, and build_bvh_from, which takes
// the boxes, gives the same tree with the boxes in leaf order beside it.
TEST(Bvh, ThreadedBuildAndBuildFromGiveTheSameTree) {
    const std::vector<Aabb> boxes = random_boxes(100000, 5, false);
    check(boxes);
    const Bvh bvh = build_bvh(boxes);
    std::vector<Aabb> taken = boxes, leaf_boxes;
    const Bvh from = build_bvh_from(std::move(taken), {}, &leaf_boxes);
    EXPECT_TRUE(taken.empty());
    ASSERT_EQ(from.nodes.size(), bvh.nodes.size());
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        EXPECT_EQ(from.nodes[i].box, bvh.nodes[i].box);
        EXPECT_EQ(from.nodes[i].first, bvh.nodes[i].first);
        EXPECT_EQ(from.nodes[i].count, bvh.nodes[i].count);
    }
    EXPECT_EQ(from.order, bvh.order);
    ASSERT_EQ(leaf_boxes.size(), boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) EXPECT_EQ(leaf_boxes[i], boxes[bvh.order[i]]);
}

TEST(Bvh, EmptyInputGivesEmptyTree) {
    Bvh bvh = build_bvh({});
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.order.empty());
}

// Leaves of up to four for many cheap primitives, fewer than one node a primitive; and the node
// array is made once with room for any tree, never regrown (a second copy at its peak), though a
// split may take one primitive off and leave more nodes than leaves of four would.
TEST(Bvh, ManyCheapPrimitivesTakeLeavesOfUpToFour) {
    EXPECT_EQ(tree_options(kManyCheapPrimitives - 1, true).min_leaf_size, 1u);
    EXPECT_EQ(tree_options(kManyCheapPrimitives, false).min_leaf_size, 1u);
    const BvhOptions options = tree_options(kManyCheapPrimitives, true);
    EXPECT_EQ(options.min_leaf_size, 4u);
    EXPECT_EQ(options.max_leaf_size, 4u);
    const std::vector<Aabb> boxes = random_boxes(50000, 6, false);
    check(boxes, options);
    const Bvh bvh = build_bvh(boxes, options);
    EXPECT_LT(bvh.nodes.size(), boxes.size());
    EXPECT_GT(build_bvh(boxes).nodes.size(), boxes.size() * 3 / 2) << "single leaves";
    EXPECT_EQ(bvh.nodes.capacity(), 2 * boxes.size()) << "the node array grew";
}

}  // namespace
}  // namespace lancer

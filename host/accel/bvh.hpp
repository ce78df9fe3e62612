#pragma once
// A bounding volume hierarchy over boxes, built with binned SAH and stored flat: the children
// of an inner node are adjacent (left, left + 1), and each leaf refers to a contiguous range of
// `order`, so a renderer can reorder its primitives once and address leaves by range.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "scene/aabb.hpp"

namespace lancer {

struct BvhNode {
    Aabb box;
    std::uint32_t first = 0;  // inner: index of the left child (right = first + 1); leaf: first of `order`
    std::uint32_t count = 0;  // 0 for inner nodes, else the number of primitives in the leaf
    bool leaf() const { return count > 0; }
};

struct Bvh {
    std::vector<BvhNode> nodes;        // nodes[0] is the root (absent when there are no boxes)
    std::vector<std::uint32_t> order;  // primitive indices in leaf order
};

struct BvhOptions {
    std::uint32_t max_leaf_size = 4;
    // Ranges of at most this many primitives are leaves whatever the SAH says: where a test costs
    // about a box's (a sphere), this halves a big tree's nodes for little more testing.
    std::uint32_t min_leaf_size = 1;
    int bins = 16;
};

// The options for a tree over `count` primitives: where there are many and each test costs about
// a box's (the shapes registry's SHAPE_CHEAP), leaves of up to four, a third of the nodes of a
// tree of single primitives, built and walked faster on both backends; a few keep single leaves,
// which are faster there (docs/performance.md).
inline constexpr std::size_t kManyCheapPrimitives = 10000;
inline BvhOptions tree_options(std::size_t count, bool cheap_tests) {
    if (cheap_tests && count >= kManyCheapPrimitives) return BvhOptions{.max_leaf_size = 4, .min_leaf_size = 4};
    return {};
}

Bvh build_bvh(std::span<const Aabb> boxes, const BvhOptions& options = {});

// The same tree over boxes it takes, freed as it copies them (no second copy held); with
// `leaf_boxes`, the boxes in leaf order come back there (leaf_boxes[i] = boxes[order[i]]).
Bvh build_bvh_from(std::vector<Aabb>&& boxes, const BvhOptions& options = {}, std::vector<Aabb>* leaf_boxes = nullptr);

// The last tree built, for a renderer that draws frame after frame: static geometry gives the
// same boxes, and then the same tree without building it again. Boxes are compared exactly,
// so any change at all rebuilds.
class BvhCache {
public:
    // The tree is shared: a renderer keeps it without a copy, and after the cache moves on. One
    // cache serves one renderer, which always asks with the same options for the same boxes.
    std::shared_ptr<const Bvh> build(std::span<const Aabb> boxes, const BvhOptions& options = {});
    std::size_t builds() const { return builds_; }  // trees built so far (for tests)

private:
    std::vector<Aabb> boxes_;
    std::shared_ptr<const Bvh> bvh_;
    std::size_t builds_ = 0;
};

// The trees over element sets that the scene shares and never changes (a mesh's triangles, a
// sphere set's spheres: held by shared_ptr<const ...>), for a renderer that draws frame after
// frame: each set's tree is built once, not at every frame or camera move. The cache holds each
// set while it holds its tree, so that the set's address names it; prune() lets go of the sets
// not asked for since the last prune (a scene's old meshes).
class ElementTreeCache {
public:
    // The tree over `set`'s elements, from `build` the first time.
    std::shared_ptr<const Bvh> tree(const std::shared_ptr<const void>& set, const std::function<Bvh()>& build);
    void prune();
    std::size_t builds() const { return builds_; }  // trees built so far (for tests)

private:
    struct Entry {
        std::shared_ptr<const void> set;
        std::shared_ptr<const Bvh> tree;
        bool asked = true;
    };
    std::unordered_map<const void*, Entry> entries_;
    std::size_t builds_ = 0;
};

}  // namespace lancer

#include "accel/bvh.hpp"

#include <algorithm>
#include <numeric>

namespace lancer {
namespace {

// Beyond this depth nodes are split at the median, which bounds the whole tree's depth by
// kSahDepth + log2(n) <= 60 for n <= 2^20: the GPU's traversal stack has 64 entries.
constexpr int kSahDepth = 40;

// Relative cost of a ray/primitive test against a ray/box test, in the SAH.
constexpr double kIntersectCost = 2.0;
constexpr double kTraversalCost = 1.0;

struct Builder {
    std::span<const Aabb> boxes;
    const BvhOptions& options;
    Bvh bvh;

    Aabb bounds(std::uint32_t begin, std::uint32_t end) const {
        Aabb b;
        for (std::uint32_t i = begin; i < end; ++i) b.extend(boxes[bvh.order[i]]);
        return b;
    }

    // Binned SAH over centroids: returns the split position in `order` (begin < mid < end), or
    // `end` when keeping the range as one leaf is cheaper.
    std::uint32_t split(std::uint32_t begin, std::uint32_t end, const Aabb& node_box, int depth) {
        std::uint32_t n = end - begin;
        Aabb centroids;
        for (std::uint32_t i = begin; i < end; ++i) centroids.extend(boxes[bvh.order[i]].center());
        glm::dvec3 extent = centroids.extent();
        int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        if (depth >= kSahDepth) {
            if (n <= options.max_leaf_size) return end;
            std::uint32_t mid = begin + n / 2;
            std::nth_element(bvh.order.begin() + begin, bvh.order.begin() + mid, bvh.order.begin() + end,
                             [&](std::uint32_t a, std::uint32_t b) {
                                 return boxes[a].center()[axis] < boxes[b].center()[axis];
                             });
            return mid;
        }
        if (!(extent[axis] > 0.0)) {
            // All centroids coincide: SAH cannot separate them; halve by count if too many.
            return n > options.max_leaf_size ? begin + n / 2 : end;
        }
        const int bins = options.bins;
        struct Bin {
            Aabb box;
            std::uint32_t count = 0;
        };
        std::vector<Bin> bin(bins);
        auto bin_of = [&](std::uint32_t prim) {
            double c = boxes[prim].center()[axis];
            int b = static_cast<int>(bins * (c - centroids.lo[axis]) / extent[axis]);
            return std::clamp(b, 0, bins - 1);
        };
        for (std::uint32_t i = begin; i < end; ++i) {
            Bin& b = bin[bin_of(bvh.order[i])];
            b.box.extend(boxes[bvh.order[i]]);
            ++b.count;
        }
        // Sweep from the right, then from the left, to cost every split between bins.
        std::vector<double> right_cost(bins, 0.0);
        Aabb right;
        std::uint32_t right_count = 0;
        for (int i = bins - 1; i > 0; --i) {
            right.extend(bin[i].box);
            right_count += bin[i].count;
            right_cost[i] = right.surface_area() * right_count;
        }
        double best = std::numeric_limits<double>::infinity();
        int best_bin = -1;
        Aabb left;
        std::uint32_t left_count = 0;
        for (int i = 0; i < bins - 1; ++i) {
            left.extend(bin[i].box);
            left_count += bin[i].count;
            if (left_count == 0 || left_count == n) continue;
            double cost = left.surface_area() * left_count + right_cost[i + 1];
            if (cost < best) {
                best = cost;
                best_bin = i;
            }
        }
        double area = node_box.surface_area();
        double leaf_cost = kIntersectCost * n;
        double split_cost = kTraversalCost + (area > 0.0 ? kIntersectCost * best / area : leaf_cost);
        if (best_bin < 0 || (split_cost >= leaf_cost && n <= options.max_leaf_size)) {
            return n > options.max_leaf_size ? begin + n / 2 : end;
        }
        auto mid = std::partition(bvh.order.begin() + begin, bvh.order.begin() + end,
                                  [&](std::uint32_t prim) { return bin_of(prim) <= best_bin; });
        return static_cast<std::uint32_t>(mid - bvh.order.begin());
    }

    void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, int depth) {
        Aabb box = bounds(begin, end);
        bvh.nodes[node].box = box;
        std::uint32_t mid = end - begin > 1 ? split(begin, end, box, depth) : end;
        if (mid == end || mid == begin) {
            bvh.nodes[node].first = begin;
            bvh.nodes[node].count = end - begin;
            return;
        }
        auto left = static_cast<std::uint32_t>(bvh.nodes.size());
        bvh.nodes.emplace_back();
        bvh.nodes.emplace_back();
        bvh.nodes[node].first = left;
        bvh.nodes[node].count = 0;
        build(left, begin, mid, depth + 1);
        build(left + 1, mid, end, depth + 1);
    }
};

}  // namespace

Bvh build_bvh(std::span<const Aabb> boxes, const BvhOptions& options) {
    Builder b{boxes, options, {}};
    if (boxes.empty()) return {};
    b.bvh.order.resize(boxes.size());
    std::iota(b.bvh.order.begin(), b.bvh.order.end(), 0u);
    b.bvh.nodes.reserve(2 * boxes.size());
    b.bvh.nodes.emplace_back();
    b.build(0, 0, static_cast<std::uint32_t>(boxes.size()), 0);
    return std::move(b.bvh);
}

const Bvh& BvhCache::build(std::span<const Aabb> boxes) {
    if (builds_ > 0 && std::equal(boxes.begin(), boxes.end(), boxes_.begin(), boxes_.end())) return bvh_;
    bvh_ = build_bvh(boxes);
    boxes_.assign(boxes.begin(), boxes.end());
    ++builds_;
    return bvh_;
}

}  // namespace lancer

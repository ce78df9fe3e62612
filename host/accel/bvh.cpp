#include "accel/bvh.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <thread>

#include "core/huge_pages.hpp"
#include "core/page_release.hpp"

namespace lancer {
namespace {

// Beyond this depth nodes are split at the median, which bounds the whole tree's depth by
// kSahDepth + log2(n) <= 60 for n <= 2^20: the GPU's traversal stack has 64 entries.
constexpr int kSahDepth = 40;

// Relative cost of a ray/primitive test against a ray/box test, in the SAH.
constexpr double kIntersectCost = 2.0;
constexpr double kTraversalCost = 1.0;

// A subtree of at least this many primitives may be built on a thread of its own.
constexpr std::uint32_t kParallelRange = 1u << 15;
constexpr int kMaxBins = 64;

// A primitive's box and index, moved along as ranges are partitioned: each pass over a range
// then reads memory in order, not through an index.
struct PrimitiveRef {
    Aabb box;
    std::uint32_t index;
};

struct Builder {
    std::span<PrimitiveRef> refs;  // all of them; each builder owns the ranges it is given
    const BvhOptions& options;
    int thread_depth;  // subtrees above this depth may go to threads of their own
    std::vector<BvhNode> nodes;

    // A range's box, and the box of its boxes' centres.
    struct Bounds {
        Aabb box, centres;
    };
    Bounds bounds(std::uint32_t begin, std::uint32_t end) const {
        Bounds b;
        for (std::uint32_t i = begin; i < end; ++i) {
            b.box.extend(refs[i].box);
            b.centres.extend(refs[i].box.center());
        }
        return b;
    }

    struct Split {
        std::uint32_t mid;  // begin < mid < end, or end: keep the range as one leaf
        std::optional<std::array<Bounds, 2>> halves;  // the halves' bounds, where the binning gave them
    };

    std::uint32_t median(std::uint32_t begin, std::uint32_t end, int axis) {
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(refs.begin() + begin, refs.begin() + mid, refs.begin() + end,
                         [&](const PrimitiveRef& a, const PrimitiveRef& b) { return a.box.center()[axis] < b.box.center()[axis]; });
        return mid;
    }

    // Binned SAH over centroids.
    Split split(std::uint32_t begin, std::uint32_t end, const Bounds& node, int depth) {
        const std::uint32_t n = end - begin;
        if (n <= options.min_leaf_size) return {end, {}};
        const Aabb& centroids = node.centres;
        const glm::dvec3 extent = centroids.extent();
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        if (depth >= kSahDepth) return {n <= options.max_leaf_size ? end : median(begin, end, axis), {}};
        // All centroids coincide: SAH cannot separate them; halve by count if too many.
        if (!(extent[axis] > 0.0)) return {n > options.max_leaf_size ? begin + n / 2 : end, {}};
        const int bins = std::clamp(options.bins, 2, kMaxBins);
        struct Bin {
            Aabb box, centres;
            std::uint32_t count = 0;
        };
        std::array<Bin, kMaxBins> bin{};
        const double lo = centroids.lo[axis], width = extent[axis];
        auto bin_of = [&](const PrimitiveRef& r) {
            return std::clamp(static_cast<int>(bins * (r.box.center()[axis] - lo) / width), 0, bins - 1);
        };
        for (std::uint32_t i = begin; i < end; ++i) {
            Bin& b = bin[bin_of(refs[i])];
            b.box.extend(refs[i].box);
            b.centres.extend(refs[i].box.center());
            ++b.count;
        }
        // Sweep from the right, then from the left, to cost every split between bins.
        std::array<double, kMaxBins> right_cost{};
        std::array<Bounds, kMaxBins> right_bounds{};
        Bounds right;
        std::uint32_t right_count = 0;
        for (int i = bins - 1; i > 0; --i) {
            right.box.extend(bin[i].box);
            right.centres.extend(bin[i].centres);
            right_count += bin[i].count;
            right_cost[i] = right.box.surface_area() * right_count;
            right_bounds[i] = right;
        }
        double best = std::numeric_limits<double>::infinity();
        int best_bin = -1;
        Bounds left, best_left;
        std::uint32_t left_count = 0;
        for (int i = 0; i < bins - 1; ++i) {
            left.box.extend(bin[i].box);
            left.centres.extend(bin[i].centres);
            left_count += bin[i].count;
            if (left_count == 0 || left_count == n) continue;
            const double cost = left.box.surface_area() * left_count + right_cost[i + 1];
            if (cost < best) {
                best = cost;
                best_bin = i;
                best_left = left;
            }
        }
        const double area = node.box.surface_area();
        const double leaf_cost = kIntersectCost * n;
        const double split_cost = kTraversalCost + (area > 0.0 ? kIntersectCost * best / area : leaf_cost);
        if (best_bin < 0 || (split_cost >= leaf_cost && n <= options.max_leaf_size))
            return {n > options.max_leaf_size ? begin + n / 2 : end, {}};
        auto mid = std::partition(refs.begin() + begin, refs.begin() + end, [&](const PrimitiveRef& r) { return bin_of(r) <= best_bin; });
        return {static_cast<std::uint32_t>(mid - refs.begin()), std::array<Bounds, 2>{best_left, right_bounds[best_bin + 1]}};
    }

    void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end, const Bounds& bounds_of_range, int depth) {
        nodes[node].box = bounds_of_range.box;
        const Split s = end - begin > 1 ? split(begin, end, bounds_of_range, depth) : Split{end, {}};
        if (s.mid == end || s.mid == begin) {
            nodes[node].first = begin;
            nodes[node].count = end - begin;
            return;
        }
        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        nodes.emplace_back();
        nodes[node].first = left;
        nodes[node].count = 0;
        const Bounds left_box = s.halves ? (*s.halves)[0] : bounds(begin, s.mid);
        const Bounds right_box = s.halves ? (*s.halves)[1] : bounds(s.mid, end);
        if (depth >= thread_depth || std::min(s.mid - begin, end - s.mid) < kParallelRange) {
            build(left, begin, s.mid, left_box, depth + 1);
            build(left + 1, s.mid, end, right_box, depth + 1);
            return;
        }
        // The right subtree on a thread of its own, into its own nodes, then appended to ours.
        Builder right{refs, options, thread_depth, {}};
        reserve_huge(right.nodes, 2 * std::size_t(end - s.mid));
        right.nodes.emplace_back();
        std::thread worker([&] { right.build(0, s.mid, end, right_box, depth + 1); });
        build(left, begin, s.mid, left_box, depth + 1);
        worker.join();
        const auto base = static_cast<std::uint32_t>(nodes.size()) - 1;  // right's node k >= 1 goes to base + k
        auto moved = [&](BvhNode n) {
            if (!n.leaf()) n.first += base;
            return n;
        };
        nodes[left + 1] = moved(right.nodes[0]);
        std::size_t k = 0;
        drain(right.nodes, [&](const BvhNode& n) {
            if (k++ > 0) nodes.push_back(moved(n));
        });
    }
};

// The tree over refs (every primitive's box and index, in any order), which it reorders to leaf order.
Bvh build_over(std::vector<PrimitiveRef>& refs, const BvhOptions& options) {
    const auto n = static_cast<std::uint32_t>(refs.size());
    int thread_depth = 0;
    for (unsigned threads = std::thread::hardware_concurrency(); threads > 1; threads /= 2) ++thread_depth;
    Builder b{refs, options, thread_depth, {}};
    // Room for the most nodes any tree of n leaves can have, whatever the leaf sizes (a split may
    // take one primitive off): the vector never grows, which would hold two copies at its peak.
    // Only the pages used are ever touched.
    reserve_huge(b.nodes, 2 * std::size_t(n));
    b.nodes.emplace_back();
    b.build(0, 0, n, b.bounds(0, n), 0);
    Bvh bvh;
    bvh.nodes = std::move(b.nodes);
    reserve_huge(bvh.order, n);
    return bvh;
}

}  // namespace

Bvh build_bvh(std::span<const Aabb> boxes, const BvhOptions& options) {
    if (boxes.empty()) return {};
    std::vector<PrimitiveRef> refs;
    reserve_huge(refs, boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) refs.push_back({boxes[i], static_cast<std::uint32_t>(i)});
    Bvh bvh = build_over(refs, options);
    for (const PrimitiveRef& r : refs) bvh.order.push_back(r.index);
    return bvh;
}

Bvh build_bvh_from(std::vector<Aabb>&& boxes, const BvhOptions& options, std::vector<Aabb>* leaf_boxes) {
    if (boxes.empty()) return {};
    std::vector<PrimitiveRef> refs;
    reserve_huge(refs, boxes.size());
    std::uint32_t index = 0;
    drain(boxes, [&](const Aabb& box) { refs.push_back({box, index++}); });
    Bvh bvh = build_over(refs, options);
    if (leaf_boxes) reserve_huge(*leaf_boxes, refs.size());
    drain(refs, [&](const PrimitiveRef& r) {
        bvh.order.push_back(r.index);
        if (leaf_boxes) leaf_boxes->push_back(r.box);
    });
    return bvh;
}

std::shared_ptr<const Bvh> BvhCache::build(std::span<const Aabb> boxes, const BvhOptions& options) {
    if (bvh_ && std::equal(boxes.begin(), boxes.end(), boxes_.begin(), boxes_.end())) return bvh_;
    bvh_.reset();  // the old tree goes before the new one is built, unless a renderer still holds it
    bvh_ = std::make_shared<const Bvh>(build_bvh(boxes, options));
    boxes_.assign(boxes.begin(), boxes.end());
    ++builds_;
    return bvh_;
}

std::shared_ptr<const Bvh> ElementTreeCache::tree(const std::shared_ptr<const void>& set, const std::function<Bvh()>& build) {
    if (auto found = entries_.find(set.get()); found != entries_.end()) {
        found->second.asked = true;
        return found->second.tree;
    }
    auto tree = std::make_shared<const Bvh>(build());  // built before it is entered: a throw leaves no entry
    ++builds_;
    entries_.emplace(set.get(), Entry{set, tree});
    return tree;
}

void ElementTreeCache::prune() {
    std::erase_if(entries_, [](const auto& e) { return !e.second.asked; });
    for (auto& [set, entry] : entries_) entry.asked = false;
}

}  // namespace lancer

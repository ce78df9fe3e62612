#include "mesh/element_tree.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include <glm/common.hpp>

#include "core/huge_pages.hpp"

namespace lancer {
namespace {

using glm::dvec3;

constexpr std::uint32_t kLeafSize = 4;

struct TreeBuilder {
    const ElementExtent& extend;
    std::vector<dvec3> centres;
    ElementTree& tree;

    void bound(ElementTree::Node& node) const {
        node.lo = dvec3(std::numeric_limits<double>::infinity());
        node.hi = -node.lo;
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) extend(tree.order[i], node.lo, node.hi);
    }

    // Splits node `index` (whose range is [first, first + count)) until its leaves are small.
    void split(std::uint32_t index) {
        std::vector<std::uint32_t> pending{index};
        while (!pending.empty()) {
            const std::uint32_t n = pending.back();
            pending.pop_back();
            ElementTree::Node node = tree.nodes[n];
            if (node.count <= kLeafSize) continue;
            dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                lo = glm::min(lo, centres[tree.order[i]]);
                hi = glm::max(hi, centres[tree.order[i]]);
            }
            const dvec3 spread = hi - lo;
            const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : spread.y >= spread.z ? 1 : 2;
            const std::uint32_t half = node.count / 2;
            auto begin = tree.order.begin() + node.first;
            std::nth_element(begin, begin + half, begin + node.count,
                             [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; });
            const auto left = static_cast<std::uint32_t>(tree.nodes.size());
            ElementTree::Node l{{}, {}, node.first, half}, r{{}, {}, node.first + half, node.count - half};
            bound(l);
            bound(r);
            tree.nodes.push_back(l);
            tree.nodes.push_back(r);
            tree.nodes[n].first = left;
            tree.nodes[n].count = 0;
            pending.push_back(left);
            pending.push_back(left + 1);
        }
    }
};

}  // namespace

ElementTree build_element_tree(std::uint32_t count, const ElementExtent& extend) {
    ElementTree tree;
    if (count == 0) return tree;
    reserve_huge(tree.order, count);
    tree.order.resize(count);
    std::iota(tree.order.begin(), tree.order.end(), 0u);
    TreeBuilder builder{extend, {}, tree};
    reserve_huge(builder.centres, count);
    for (std::uint32_t i = 0; i < count; ++i) {
        dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
        extend(i, lo, hi);
        builder.centres.push_back(0.5 * (lo + hi));
    }
    reserve_huge(tree.nodes, 2 * count / kLeafSize + 1);
    ElementTree::Node root{{}, {}, 0, count};
    builder.bound(root);
    tree.nodes.push_back(root);
    builder.split(0);
    return tree;
}

}  // namespace lancer

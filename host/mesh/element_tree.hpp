#pragma once
// The CPU reference's own tree over a shared set of elements (a mesh's triangles, a sphere set's
// spheres), in double: median splits of the elements' box centres along the widest axis, down to
// leaves of at most 4. Written apart from host/accel/bvh.cpp's binned SAH, which the GPU uses, so
// that the reference does not share the tree it checks.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

namespace lancer {

// Each node's box holds its elements exactly; children of an inner node are adjacent (first,
// first + 1); a leaf refers to `count` entries of `order` from `first`.
struct ElementTree {
    struct Node {
        glm::dvec3 lo, hi;
        std::uint32_t first = 0;
        std::uint32_t count = 0;  // 0: inner node
    };
    std::vector<Node> nodes;           // nodes[0] is the root
    std::vector<std::uint32_t> order;  // element indices in leaf order
};

// extend(i, lo, hi) widens [lo, hi] to hold element i.
using ElementExtent = std::function<void(std::uint32_t, glm::dvec3&, glm::dvec3&)>;
ElementTree build_element_tree(std::uint32_t count, const ElementExtent& extend);

}  // namespace lancer

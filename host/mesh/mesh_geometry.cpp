#include "mesh/mesh_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace lancer {
namespace {

using glm::dvec3;

dvec3 angle_weighted(const dvec3& a, const dvec3& b, const dvec3& c, const dvec3& face) {
    const dvec3 u = b - a, v = c - a;
    const double lu = glm::length(u), lv = glm::length(v);
    if (!(lu > 0.0) || !(lv > 0.0)) return dvec3(0.0);
    return face * std::acos(std::clamp(glm::dot(u, v) / (lu * lv), -1.0, 1.0));
}

void compute_normals(TriangleMesh& m) {
    m.normals.assign(m.positions.size(), dvec3(0.0));
    for (const auto& t : m.triangles) {
        const dvec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
        const dvec3 n = glm::cross(b - a, c - a);
        const double length = glm::length(n);
        if (!(length > 0.0)) continue;
        const dvec3 face = n / length;
        m.normals[t[0]] += angle_weighted(a, b, c, face);
        m.normals[t[1]] += angle_weighted(b, c, a, face);
        m.normals[t[2]] += angle_weighted(c, a, b, face);
    }
    // A vertex whose triangles cancel (a fold) keeps a zero normal: the shaders then use the
    // triangle's own there.
    for (dvec3& n : m.normals) {
        const double length = glm::length(n);
        n = length > 0.0 ? n / length : dvec3(0.0);
    }
}

// Tree building: median split of the triangles' centres along the widest axis of their spread,
// down to leaves of at most this many triangles.
constexpr std::uint32_t kLeafSize = 4;

struct TreeBuilder {
    const TriangleMesh& mesh;
    std::vector<dvec3> centres;
    MeshTree& tree;

    void bound(MeshTree::Node& node) const {
        node.lo = dvec3(std::numeric_limits<double>::infinity());
        node.hi = -node.lo;
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
            for (std::uint32_t v : mesh.triangles[tree.order[i]]) {
                node.lo = glm::min(node.lo, mesh.positions[v]);
                node.hi = glm::max(node.hi, mesh.positions[v]);
            }
    }

    // Splits node `index` (whose range is [first, first + count)) until its leaves are small.
    void split(std::uint32_t index) {
        std::vector<std::uint32_t> pending{index};
        while (!pending.empty()) {
            const std::uint32_t n = pending.back();
            pending.pop_back();
            MeshTree::Node node = tree.nodes[n];
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
            MeshTree::Node l{{}, {}, node.first, half}, r{{}, {}, node.first + half, node.count - half};
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

MeshTree build_mesh_tree(const TriangleMesh& mesh) {
    MeshTree tree;
    if (mesh.triangles.empty()) return tree;
    tree.order.resize(mesh.triangles.size());
    std::iota(tree.order.begin(), tree.order.end(), 0u);
    TreeBuilder builder{mesh, {}, tree};
    builder.centres.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        builder.centres.push_back((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0);
    tree.nodes.reserve(2 * mesh.triangles.size() / kLeafSize + 1);
    MeshTree::Node root{{}, {}, 0, static_cast<std::uint32_t>(mesh.triangles.size())};
    builder.bound(root);
    tree.nodes.push_back(root);
    builder.split(0);
    return tree;
}

MeshGeometry::MeshGeometry(TriangleMesh mesh) : mesh_(std::move(mesh)) {
    file_normals_ = !mesh_.normals.empty();
    if (!file_normals_) compute_normals(mesh_);
    lo_ = dvec3(std::numeric_limits<double>::infinity());
    hi_ = -lo_;
    for (const auto& t : mesh_.triangles)
        for (std::uint32_t v : t) {
            lo_ = glm::min(lo_, mesh_.positions[v]);
            hi_ = glm::max(hi_, mesh_.positions[v]);
        }
}

const MeshTree& MeshGeometry::tree() const {
    std::call_once(tree_built_, [this] { tree_ = build_mesh_tree(mesh_); });
    return tree_;
}

}  // namespace lancer

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

}  // namespace

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

const ElementTree& MeshGeometry::tree() const {
    std::call_once(tree_built_, [this] {
        tree_ = build_element_tree(static_cast<std::uint32_t>(mesh_.triangles.size()),
                                   [this](std::uint32_t i, dvec3& lo, dvec3& hi) {
                                       for (std::uint32_t v : mesh_.triangles[i]) {
                                           lo = glm::min(lo, mesh_.positions[v]);
                                           hi = glm::max(hi, mesh_.positions[v]);
                                       }
                                   });
    });
    return tree_;
}

}  // namespace lancer

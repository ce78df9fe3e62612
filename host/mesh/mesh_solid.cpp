#include "mesh/mesh_solid.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/error.hpp"

namespace lancer::mesh {
namespace {

struct PositionHash {
    std::size_t operator()(const glm::dvec3& p) const {
        std::size_t h = 0;
        for (int i = 0; i < 3; ++i) h = h * 0x9E3779B97F4A7C15ull ^ std::bit_cast<std::uint64_t>(p[i] + 0.0);  // +0.0: -0 is 0
        return h;
    }
};

std::string point(const glm::dvec3& p) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x, p.y, p.z); }

}  // namespace

int outward_side(const TriangleMesh& mesh) {
    // One number per distinct position: a reader may repeat a position for its normals or (u, v).
    std::unordered_map<glm::dvec3, std::uint32_t, PositionHash> ids;
    std::vector<std::uint32_t> id(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        id[i] = ids.try_emplace(mesh.positions[i] + 0.0, std::uint32_t(ids.size())).first->second;

    // Each edge's uses, by its two ends (the smaller first), counted in each direction.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::array<int, 2>> edges;
    std::vector<std::uint32_t> first_position(ids.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) first_position[id[i]] = std::uint32_t(i);
    double volume = 0.0;
    const glm::dvec3 centre = mesh.positions.empty() ? glm::dvec3(0.0) : mesh.positions[0];
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = id[t[k]], b = id[t[(k + 1) % 3]];
            ++edges[{std::min(a, b), std::max(a, b)}][a < b ? 0 : 1];
        }
        const glm::dvec3 p = mesh.positions[t[0]] - centre, q = mesh.positions[t[1]] - centre, r = mesh.positions[t[2]] - centre;
        volume += glm::dot(p, glm::cross(q, r)) / 6.0;
    }
    for (const auto& [ends, uses] : edges) {
        if (uses[0] == 1 && uses[1] == 1) continue;
        const std::string where = fmt::format("the edge from {} to {}", point(mesh.positions[first_position[ends.first]]),
                                              point(mesh.positions[first_position[ends.second]]));
        const int triangles = uses[0] + uses[1];
        if (triangles == 1) throw UserError(fmt::format("it is not closed: {} belongs to one triangle only", where));
        if (triangles > 2)
            throw UserError(fmt::format("{} belongs to {} triangles (a closed surface's edge to two)", where, triangles));
        throw UserError(
            fmt::format("its two triangles at {} run it the same way: their fronts face opposite sides of the surface", where));
    }
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const double size = glm::length(hi - lo);
    if (edges.empty() || !(std::abs(volume) > 1e-9 * size * size * size))
        throw UserError(fmt::format("it encloses no volume (its signed volume is {:.3g})", volume));
    return volume > 0.0 ? 1 : -1;
}

}  // namespace lancer::mesh

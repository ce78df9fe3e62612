#include "mesh/mesh_assembly.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "core/magnitude.hpp"

namespace lancer::mesh {

std::optional<std::string> coordinate_problem(double x) {
    if (!std::isfinite(x)) return fmt::format("{} is not a finite number", x);
    if (std::abs(x) > kMaxMagnitude)
        return fmt::format("{:g} is outside lancer's range of numbers (magnitude at most {:g})", x, kMaxMagnitude);
    return std::nullopt;
}

std::optional<glm::dvec3> unit_normal(const glm::dvec3& n) {
    // Scaled by its largest component first, so that neither 1e-200 nor 1e200 under- or overflows.
    const double largest = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
    if (!(largest > 0.0) || !std::isfinite(largest)) return std::nullopt;
    return glm::normalize(n / largest);
}

void TriangleFan::add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::optional<std::uint32_t> material) {
    const glm::dvec3& p = mesh_.positions[a];
    const glm::dvec3 area = glm::cross(mesh_.positions[b] - p, mesh_.positions[c] - p);
    if (area == glm::dvec3(0.0)) {  // equal corners, or collinear ones: no ray can hit it
        ++mesh_.skipped_degenerate;
        return;
    }
    mesh_.triangles.push_back({a, b, c});
    if (material) mesh_.triangle_materials.push_back(*material);
}

void TriangleFan::add_polygon(std::span<const std::uint32_t> corners, std::optional<std::uint32_t> material) {
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) add_triangle(corners[0], corners[i], corners[i + 1], material);
}

void require_triangles(const TriangleMesh& mesh, const std::string& file) {
    if (!mesh.triangles.empty()) return;
    if (mesh.skipped_degenerate > 0)
        throw SceneError({file, 0, 0}, fmt::format("the mesh has no triangles: all {} of them have zero area",
                                                   mesh.skipped_degenerate));
    throw SceneError({file, 0, 0}, "the mesh has no triangles (no faces in the file)");
}

}  // namespace lancer::mesh

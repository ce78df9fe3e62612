#pragma once
// What both readers do with the numbers they read: check them against lancer's range, fan polygons
// into triangles, leave out those of zero area, and refuse a mesh with nothing to show.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "mesh/triangle_mesh.hpp"

namespace lancer::mesh {

// Why `x` cannot be a coordinate (not finite, or beyond kMaxMagnitude); nullopt when it can.
std::optional<std::string> coordinate_problem(double x);

// `n` scaled to unit length; nullopt when it has none (zero, or not finite).
std::optional<glm::dvec3> unit_normal(const glm::dvec3& n);

// Appends triangles to a mesh whose positions are already read. Indices must be valid.
class TriangleFan {
public:
    explicit TriangleFan(TriangleMesh& mesh) : mesh_(mesh) {}
    // A polygon of corners.size() >= 3 corners as the fan (c0, c_i, c_i+1); a material index
    // goes with each triangle kept when `material` is set.
    void add_polygon(std::span<const std::uint32_t> corners, std::optional<std::uint32_t> material);
    void add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::optional<std::uint32_t> material);

private:
    TriangleMesh& mesh_;
};

// Throws SceneError at `file` (line 0) when the mesh has no triangle: an empty mesh is an error,
// not an invisible object.
void require_triangles(const TriangleMesh& mesh, const std::string& file);

}  // namespace lancer::mesh

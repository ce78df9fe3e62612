#pragma once
// A mesh as the scene holds it: the file's triangles (shared by every object placed from them),
// with vertex normals where the file has none (for smooth shading) and, built on first use by the
// CPU reference, its own tree over the triangles. The GPU flattens the triangles into its BVH.
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "mesh/element_tree.hpp"
#include "mesh/triangle_mesh.hpp"

namespace lancer {

class MeshGeometry {
public:
    // Takes the file's mesh; where it has no normals, computes them (each vertex: the angle-
    // weighted mean of its triangles' normals, Thürmer and Wüthrich's rule, which does not
    // depend on how a polygon was cut into triangles).
    explicit MeshGeometry(TriangleMesh mesh);

    const TriangleMesh& mesh() const { return mesh_; }
    bool file_normals() const { return file_normals_; }
    glm::dvec3 lo() const { return lo_; }
    glm::dvec3 hi() const { return hi_; }
    // Built on the first call (thread-safe): only the CPU reference traverses it.
    const ElementTree& tree() const;

private:
    TriangleMesh mesh_;
    bool file_normals_ = false;
    glm::dvec3 lo_{0.0}, hi_{0.0};
    mutable std::once_flag tree_built_;
    mutable ElementTree tree_;
};

}  // namespace lancer

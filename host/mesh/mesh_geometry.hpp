#pragma once
// A mesh as the scene holds it: the file's triangles (shared by every object placed from them),
// with vertex normals where the file has none (for smooth shading) and, built on first use by the
// CPU reference, its own tree over the triangles. The GPU flattens the triangles into its BVH.
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "mesh/triangle_mesh.hpp"

namespace lancer {

// A bounding volume hierarchy over a mesh's triangles, in double: each node's box holds its
// triangles exactly; children of an inner node are adjacent (first, first + 1); a leaf refers to
// `count` entries of `order` from `first`.
struct MeshTree {
    struct Node {
        glm::dvec3 lo, hi;
        std::uint32_t first = 0;
        std::uint32_t count = 0;  // 0: inner node
    };
    std::vector<Node> nodes;           // nodes[0] is the root
    std::vector<std::uint32_t> order;  // triangle indices in leaf order
};
MeshTree build_mesh_tree(const TriangleMesh& mesh);

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
    const MeshTree& tree() const;

private:
    TriangleMesh mesh_;
    bool file_normals_ = false;
    glm::dvec3 lo_{0.0}, hi_{0.0};
    mutable std::once_flag tree_built_;
    mutable MeshTree tree_;
};

}  // namespace lancer

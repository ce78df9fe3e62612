#pragma once
// What lancer's mesh readers accept at most (docs/meshes.md).
#include <cstddef>
#include <cstdint>
#include <limits>

namespace lancer::mesh {

// A mesh file is read into memory whole; 2 GiB holds some 60 million triangles of binary PLY.
constexpr std::size_t kMaxMeshFileBytes = std::size_t(1) << 31;
// Indices are 32-bit (TriangleMesh::triangles): one vertex more would not have a name.
constexpr std::uint64_t kMaxMeshVertices = std::numeric_limits<std::uint32_t>::max();

}  // namespace lancer::mesh

#pragma once
// Mesh files: the reader for a file's format, chosen by its extension (.obj, .ply).
#include <string>

#include "mesh/triangle_mesh.hpp"

namespace lancer {

// Throws SceneError at the problem's line (text) or byte offset (binary) in the file.
TriangleMesh read_mesh_file(const std::string& path);

}  // namespace lancer

#pragma once
// Reading a mesh file (docs/meshes.md): the reader is chosen by the file name's extension, .obj
// (obj_reader.hpp) or .ply (ply_reader.hpp), in any case. Every problem with the file (unreadable,
// over kMaxMeshFileBytes, malformed, out of lancer's range, no triangles) is a SceneError that
// names the file and where in it: line and column for text, "byte N" in the message for binary PLY.
#include <string>

#include "mesh/triangle_mesh.hpp"

namespace lancer {

TriangleMesh read_mesh_file(const std::string& path);

namespace mesh {
// The file name's extension in lower case (".ply"), by which the readers are chosen.
std::string lower_extension(const std::string& path);

// The file's bytes, at most kMaxMeshFileBytes. Throws UserError with the reason ("No such file or
// directory", "it is larger than..."); the caller says which file and who named it.
std::string read_mesh_bytes(const std::string& path);
// The same, the reason as a SceneError at the file (line 0).
std::string read_mesh_file_bytes(const std::string& path);

}  // namespace mesh
}  // namespace lancer

#include "mesh/mesh_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/file_reading.hpp"
#include "mesh/mesh_limits.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/ply_reader.hpp"

namespace lancer {
namespace mesh {

std::string lower_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

std::string read_mesh_bytes(const std::string& path) {
    FileText file = read_file(path, kMaxMeshFileBytes);
    if (!file.complete)
        throw UserError(fmt::format("it is larger than the limit of {} GiB for mesh files", kMaxMeshFileBytes >> 30));
    return std::move(file.text);
}

std::string read_mesh_file_bytes(const std::string& path) {
    try {
        return read_mesh_bytes(path);
    } catch (const SceneError&) {
        throw;
    } catch (const UserError& e) {
        throw SceneError({path, 0, 0}, e.what());
    }
}

}  // namespace mesh

TriangleMesh read_mesh_file(const std::string& path) {
    const std::string extension = mesh::lower_extension(path);
    if (extension == ".obj") return mesh::read_obj_file(path);
    if (extension == ".ply") return mesh::read_ply(mesh::read_mesh_file_bytes(path), path);
    throw SceneError({path, 0, 0}, fmt::format("lancer reads meshes from .obj and .ply files (by the name's extension), not {}",
                                               extension.empty() ? "a name without an extension" : "'" + extension + "'"));
}

}  // namespace lancer

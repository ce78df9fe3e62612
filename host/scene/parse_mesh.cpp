// The mesh object: a triangle mesh from a file (docs/scene-format.md, "Meshes").
//   [[object]]
//   type = "mesh"
//   file = "bunny.obj"     OBJ or PLY, relative to the scene file
//   smooth = true          interpolate vertex normals (default: where the file has them)
#include <filesystem>
#include <map>
#include <mutex>

#include <fmt/format.h>
#include <glm/matrix.hpp>

#include "mesh/mesh_file.hpp"
#include "scene/parse_shapes.hpp"
#include "scene/parse_surfaces.hpp"
#include "scene/shape_bounds.hpp"

namespace lancer {
namespace {

// A file placed many times (a declared object, a group repeated) is read once while any scene
// holds it; a file changed since (hot reload) is read again.
std::shared_ptr<const MeshGeometry> mesh_geometry(const std::filesystem::path& path) {
    struct Entry {
        std::filesystem::file_time_type written;
        std::uintmax_t size;
        std::weak_ptr<const MeshGeometry> geometry;
    };
    static std::mutex mutex;
    static std::map<std::string, Entry> cache;
    std::error_code error;
    const std::filesystem::path key = std::filesystem::absolute(path, error);
    const auto written = std::filesystem::last_write_time(path, error);
    const auto size = std::filesystem::file_size(path, error);
    if (!error) {
        std::lock_guard lock(mutex);
        auto found = cache.find(key.string());
        if (found != cache.end() && found->second.written == written && found->second.size == size)
            if (auto geometry = found->second.geometry.lock()) return geometry;
    }
    auto geometry = std::make_shared<const MeshGeometry>(read_mesh_file(path.string()));
    if (!error) {
        std::lock_guard lock(mutex);
        cache[key.string()] = Entry{written, size, geometry};
    }
    return geometry;
}

}  // namespace

Shape read_mesh(TableReader& t, const glm::dmat4& to_world) {  // placed by place(), as the other shapes
    Mesh mesh;
    const std::string name = t.required_string("file");
    const std::filesystem::path path = std::filesystem::path(t.file()).parent_path() / name;
    try {
        mesh.geometry = mesh_geometry(path);
    } catch (const SceneError& e) {
        if (e.where().line > 0) throw;  // a problem on a line of the file: its own place
        throw SceneError(t.location("file"), fmt::format("cannot read mesh file '{}': {}", path.string(), e.what()));
    } catch (const UserError& e) {
        throw SceneError(t.location("file"), fmt::format("cannot read mesh file '{}': {}", path.string(), e.what()));
    }
    mesh.source_file = path.string();
    mesh.smooth = t.boolean("smooth", mesh.geometry->file_normals());
    Object placed{mesh, Placement{to_world, glm::inverse(to_world), true}};
    const std::optional<Aabb> box = object_bounds(placed);
    check_world_extent(t, t.has("transform") ? "transform" : "file", box->lo, box->hi);
    return mesh;
}

}  // namespace lancer

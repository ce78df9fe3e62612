// The mesh object: a triangle mesh from a file (docs/scene-format.md, "Meshes").
//   [[object]]
//   type = "mesh"
//   file = "bunny.obj"     OBJ or PLY, relative to the scene file
//   smooth = true          interpolate vertex normals (default: where the file has them)
#include <filesystem>

#include <fmt/format.h>
#include <glm/matrix.hpp>

#include "mesh/mesh_file.hpp"
#include "scene/file_cache.hpp"
#include "scene/parse_shapes.hpp"
#include "scene/parse_surfaces.hpp"
#include "scene/shape_bounds.hpp"

namespace lancer {

Shape read_mesh(TableReader& t, const glm::dmat4& to_world) {  // placed by place(), as the other shapes
    Mesh mesh;
    const std::string name = t.required_string("file");
    const std::filesystem::path path = std::filesystem::path(t.file().str()).parent_path() / name;
    try {
        mesh.geometry = shared_from_file<MeshGeometry>(path, "", [&] {
            return std::make_shared<const MeshGeometry>(read_mesh_file(path.string()));
        });
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

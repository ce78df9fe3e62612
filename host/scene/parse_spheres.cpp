// The sphere set object: many spheres from a PLY point set (docs/scene-format.md, "Sphere sets").
//   [[object]]
//   type = "spheres"
//   file = "points.ply"    the vertex element's x y z (radius) (red green blue), relative to the scene file
//   radius = 0.1           every sphere's, where the file gives none
#include <filesystem>

#include <fmt/format.h>
#include <glm/matrix.hpp>

#include "mesh/mesh_file.hpp"
#include "scene/file_cache.hpp"
#include "scene/parse_surfaces.hpp"
#include "scene/shape_bounds.hpp"

namespace lancer {

Shape read_spheres(TableReader& t, const glm::dmat4& to_world) {  // placed by place(), as the other shapes
    SphereSet set;
    const std::string name = t.required_string("file");
    const std::filesystem::path path = std::filesystem::path(t.file().str()).parent_path() / name;
    std::optional<double> radius;
    if (t.has("radius")) {
        radius = t.number("radius", 0.0);
        if (!(*radius > 0.0)) t.fail("radius", "radius must be > 0");
    }
    if (mesh::lower_extension(path.string()) != ".ply")
        t.fail("file", fmt::format("a sphere set is read from a PLY point set (a .ply file), not '{}'", name));
    try {
        set.cloud = shared_from_file<SphereCloud>(path, radius ? fmt::format("{}", *radius) : "", [&] {
            return mesh::read_sphere_ply(mesh::read_mesh_file_bytes(path.string()), path.string(), radius);
        });
    } catch (const SceneError& e) {
        if (e.where().line > 0) throw;  // a problem on a line of the file: its own place
        throw SceneError(t.location("file"), fmt::format("cannot read point set '{}': {}", path.string(), e.what()));
    } catch (const UserError& e) {  // the file's radius and the object's: at the object's key
        throw SceneError(t.location(radius ? "radius" : "file"), fmt::format("point set '{}': {}", path.string(), e.what()));
    }
    set.source_file = path.string();
    Object placed{set, Placement{to_world, glm::inverse(to_world), true}};
    const std::optional<Aabb> box = object_bounds(placed);
    check_world_extent(t, t.has("transform") ? "transform" : "file", box->lo, box->hi);
    return set;
}

}  // namespace lancer

#include "scene/mesh_materials.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "scene/limits.hpp"

namespace lancer {

// MTL's Phong terms on lancer's: Kd is the colour under lancer's own diffuse and ambient (so
// that a file's materials sit among the scene's), Ks's mean the highlight, Ns its exponent;
// d < 1 passes the rest of the light straight through (MTL's Tf and Ni are not read: no bending).
std::vector<std::uint32_t> add_mesh_materials(const MeshGeometry& geometry, const TableReader& t, Scene& scene,
                                              TextureLibrary& textures) {
    std::vector<std::uint32_t> indices;
    for (const MeshMaterial& file : geometry.mesh().materials) {
        Material m;
        m.name = file.name;
        m.color = file.diffuse;
        m.specular = (file.specular.r + file.specular.g + file.specular.b) / 3.0;
        m.shininess = std::max(file.shininess, 1.0);
        if (file.opacity < 1.0) m.transmission = dvec3(1.0 - file.opacity);
        if (!file.diffuse_map.empty()) {
            ImageTexture texture;
            texture.path = file.diffuse_map;
            texture.image = textures.load(t, "file", file.diffuse_map, file.diffuse_map);
            m.texture = texture;
            m.color = dvec3(1.0);  // the map is the colour (MTL multiplies it by Kd; lancer's own files do not set both)
        }
        if (scene.materials.size() >= static_cast<std::size_t>(limits::kMaxMaterials))
            t.fail("file", fmt::format("too many materials with the mesh files' (the limit is {})", limits::kMaxMaterials));
        indices.push_back(static_cast<std::uint32_t>(scene.materials.size()));
        scene.materials.push_back(m);
    }
    return indices;
}

std::vector<std::uint32_t> add_point_colors(const SphereCloud& cloud, std::uint32_t base, const TableReader& t, Scene& scene) {
    std::vector<std::uint32_t> indices;
    for (const dvec3& color : cloud.palette()) {
        Material m = scene.materials.at(base);
        m.color = color;
        m.checker.reset();
        if (scene.materials.size() >= static_cast<std::size_t>(limits::kMaxMaterials))
            t.fail("file", fmt::format("too many materials with the point sets' colours (the limit is {})", limits::kMaxMaterials));
        indices.push_back(static_cast<std::uint32_t>(scene.materials.size()));
        scene.materials.push_back(std::move(m));
    }
    return indices;
}

}  // namespace lancer

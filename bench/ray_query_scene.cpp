#include "ray_query_scene.hpp"

#include <map>
#include <string>

#include "accel/bvh.hpp"
#include "core/error.hpp"
#include "scene/camera.hpp"

namespace lancer::bench {

std::size_t MeshSet::placed_triangles() const {
    std::size_t n = 0;
    for (const MeshInstance& i : instances) n += meshes[i.mesh].triangle_count;
    return n;
}

MeshSet gather_meshes(const Scene& scene) {
    MeshSet set;
    std::map<const MeshGeometry*, std::uint32_t> known;  // each file's triangles once, however often placed
    for (const Object& o : scene.objects) {
        const auto* mesh = std::get_if<Mesh>(&o.shape);
        if (!mesh) throw UserError(scene.path + ": the ray query benchmark traces meshes only");
        if (o.material != scene.objects.front().material || !mesh->part_materials.empty())
            throw UserError(scene.path + ": the ray query benchmark shades one material");
        const MeshGeometry* geometry = mesh->geometry.get();
        auto [found, added] = known.try_emplace(geometry, static_cast<std::uint32_t>(set.meshes.size()));
        if (added) {
            const TriangleMesh& m = geometry->mesh();
            MeshRange range{static_cast<std::uint32_t>(set.positions.size() / 3), static_cast<std::uint32_t>(m.positions.size()),
                            static_cast<std::uint32_t>(set.indices.size()), static_cast<std::uint32_t>(m.triangles.size())};
            for (const glm::dvec3& p : m.positions) set.positions.insert(set.positions.end(), {float(p.x), float(p.y), float(p.z)});
            for (const auto& t : m.triangles) set.indices.insert(set.indices.end(), t.begin(), t.end());
            set.meshes.push_back(range);
        }
        MeshInstance instance{found->second, {}};
        const glm::dmat4 to_world = o.placement ? o.placement->to_world : glm::dmat4(1.0);
        for (int row = 0; row < 3; ++row)
            for (int column = 0; column < 4; ++column) instance.to_world[row * 4 + column] = float(to_world[column][row]);
        set.instances.push_back(instance);
    }
    if (set.instances.empty()) throw UserError(scene.path + ": no mesh to trace");
    return set;
}

ViewBlock view_block(const Scene& scene) {
    if (scene.lights.size() != 1 || scene.lights[0].type != LightType::Point || scene.lights[0].falloff != Falloff::None)
        throw UserError(scene.path + ": the ray query benchmark lights the scene with one point light, no fall-off");
    const RenderSettings& r = scene.render;
    const CameraBasis camera = make_camera_basis(scene.camera, r.width, r.height);
    const Material& m = scene.materials.at(scene.objects.front().material);
    if (m.specular != 0.0 || m.spawns_secondary_rays() || m.checker || m.texture || m.pattern || m.bump)
        throw UserError(scene.path + ": the ray query benchmark shades a plain matte material");
    const Light& light = scene.lights[0];
    ViewBlock v{};
    v.eye = glm::vec4(glm::vec3(camera.eye), 0.0f);
    v.forward = glm::vec4(glm::vec3(camera.forward), 0.0f);
    v.right = glm::vec4(glm::vec3(camera.right), 0.0f);
    v.up = glm::vec4(glm::vec3(camera.up), 0.0f);
    v.light_position = glm::vec4(glm::vec3(light.position), 0.0f);
    v.light_color = glm::vec4(glm::vec3(light.emitted()), 0.0f);
    v.ambient = glm::vec4(glm::vec3(m.ambient * m.color * scene.ambient), 0.0f);
    v.diffuse = glm::vec4(glm::vec3(m.diffuse * m.color), 0.0f);
    v.background = glm::vec4(glm::vec3(r.background), 0.0f);
    v.size = glm::uvec4(static_cast<unsigned>(r.width), static_cast<unsigned>(r.height), 0u, 0u);
    return v;
}

void order_as_lancer(MeshSet& set) {
    std::vector<Aabb> mesh_boxes;
    for (const MeshRange& mesh : set.meshes) {
        const auto vertex = [&](std::uint32_t index) {
            const float* p = &set.positions[3 * (std::size_t(mesh.first_vertex) + index)];
            return dvec3(p[0], p[1], p[2]);
        };
        std::uint32_t* triangles = &set.indices[mesh.first_index];
        std::vector<Aabb> boxes(mesh.triangle_count);
        for (std::uint32_t t = 0; t < mesh.triangle_count; ++t)
            for (int k = 0; k < 3; ++k) boxes[t].extend(vertex(triangles[3 * t + k]));
        const Bvh bvh = build_bvh(boxes);
        const std::vector<std::uint32_t> before(triangles, triangles + 3 * std::size_t(mesh.triangle_count));
        for (std::uint32_t t = 0; t < mesh.triangle_count; ++t)
            for (int k = 0; k < 3; ++k) triangles[3 * t + k] = before[3 * std::size_t(bvh.order[t]) + k];
        mesh_boxes.push_back(bvh.nodes.empty() ? Aabb{} : bvh.nodes.front().box);
    }
    // Each instance's world box: its mesh's box's corners, placed.
    std::vector<Aabb> boxes(set.instances.size());
    for (std::size_t i = 0; i < set.instances.size(); ++i) {
        const Aabb& local = mesh_boxes[set.instances[i].mesh];
        const auto& m = set.instances[i].to_world;
        for (int corner = 0; corner < 8; ++corner) {
            const dvec3 p(corner & 1 ? local.hi.x : local.lo.x, corner & 2 ? local.hi.y : local.lo.y,
                          corner & 4 ? local.hi.z : local.lo.z);
            boxes[i].extend(dvec3(m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
                                  m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]));
        }
    }
    const Bvh bvh = build_bvh(boxes);
    const std::vector<MeshInstance> before = set.instances;
    for (std::size_t i = 0; i < before.size(); ++i) set.instances[i] = before[bvh.order[i]];
}

}  // namespace lancer::bench

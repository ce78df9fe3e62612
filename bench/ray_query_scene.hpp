#pragma once
// What the driver's path of bench/ray_query.sh takes from a lancer scene: every mesh once (its
// float vertices and triangles, one after another), every object that places one (an instance),
// and the camera, the one light and the one matte material as the shader's uniform block.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "scene/scene.hpp"

namespace lancer::bench {

struct MeshRange {
    std::uint32_t first_vertex = 0, vertex_count = 0;
    std::uint32_t first_index = 0, triangle_count = 0;
};

struct MeshInstance {
    std::uint32_t mesh = 0;                // into MeshSet::meshes
    std::array<float, 12> to_world{};     // object -> world, 3 x 4 row-major (VkTransformMatrixKHR)
};

struct MeshSet {
    std::vector<float> positions;          // x, y, z per vertex
    std::vector<std::uint32_t> indices;    // three per triangle, relative to the mesh's first vertex
    std::vector<MeshRange> meshes;
    std::vector<MeshInstance> instances;
    std::size_t placed_triangles() const;  // over every instance
};

// The shader's uniform block (bench/ray_query.comp, View), std140.
struct ViewBlock {
    glm::vec4 eye, forward, right, up;
    glm::vec4 light_position, light_color;
    glm::vec4 ambient, diffuse, background;
    glm::uvec4 size;
};

// Throws UserError where the scene holds anything but meshes, or not exactly one point light,
// or meshes of different materials: the benchmark traces nothing else.
MeshSet gather_meshes(const Scene& scene);
ViewBlock view_block(const Scene& scene);

// Puts each mesh's triangles, and the instances, in the order of the leaves of lancer's own
// trees over them (accel/bvh.hpp's binned SAH over their boxes). Mesa 25.0's lavapipe builds its
// trees by halving the primitives in the order given, so the order decides its trees' quality.
void order_as_lancer(MeshSet& set);

}  // namespace lancer::bench

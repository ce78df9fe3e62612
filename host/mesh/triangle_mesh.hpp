#pragma once
// A triangle mesh as read from a file (OBJ, PLY), before any scene or renderer sees it: shared
// vertices, so that two triangles meeting at an edge name the same two positions and a watertight
// intersector sees identical numbers on both sides (no cracks).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace lancer {

// A material the file names (OBJ's MTL): what lancer's material takes from it unless the scene's
// object sets its own (docs/scene-format.md, "Meshes").
struct MeshMaterial {
    std::string name;
    glm::dvec3 diffuse{0.8};    // Kd
    glm::dvec3 specular{0.0};   // Ks
    double shininess = 0.0;     // Ns
    double opacity = 1.0;       // d (1 - Tr)
    std::string diffuse_map;    // map_Kd, resolved against the MTL file's folder; empty: none
};

struct TriangleMesh {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;  // one per position, unit; empty: the file has none
    std::vector<glm::dvec2> uvs;      // one per position; empty: the file has none
    std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into positions (and normals, uvs), counter-clockwise seen from the front
    std::vector<std::uint32_t> triangle_materials;        // one per triangle, into materials; empty: none
    std::vector<MeshMaterial> materials;
    std::vector<std::string> companion_files;  // read besides the mesh's own file (an OBJ's MTL files)
    std::size_t skipped_degenerate = 0;  // zero-area triangles the reader left out (they cannot be seen)
};

}  // namespace lancer

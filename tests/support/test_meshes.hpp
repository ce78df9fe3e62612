#pragma once
// Closed triangle meshes made in code, for the mesh tests: an icosphere (an icosahedron whose
// triangles are cut in four, n times, with the new vertices pushed out to the sphere) and a
// latitude-longitude sphere, both with shared vertices and outward winding; and a cube as OBJ text
// and as a closed Bezier surface.
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "mesh/triangle_mesh.hpp"

namespace lancer::test {

inline TriangleMesh icosphere(int subdivisions, const glm::dvec3& centre = glm::dvec3(0.0), double radius = 1.0) {
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> unit = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                                    {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (auto& v : unit) v = glm::normalize(v);
    std::vector<std::array<std::uint32_t, 3>> faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
                                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                       {3, 9, 4},  {3, 4, 2}, {3, 2, 6}, {3, 6, 8},  {3, 8, 9},
                                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middles;
        auto middle = [&](std::uint32_t a, std::uint32_t b) {
            auto key = std::minmax(a, b);
            auto [it, added] = middles.try_emplace(key, static_cast<std::uint32_t>(unit.size()));
            if (added) unit.push_back(glm::normalize(unit[a] + unit[b]));
            return it->second;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        for (const auto& f : faces) {
            const std::uint32_t ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }
    TriangleMesh m;
    for (const auto& v : unit) {
        m.positions.push_back(centre + radius * v);
        m.normals.push_back(v);
    }
    m.triangles = std::move(faces);
    return m;
}

// `rings` bands of latitude, 2 * rings segments of longitude; the poles are single vertices.
inline TriangleMesh uv_sphere(int rings, const glm::dvec3& centre = glm::dvec3(0.0), double radius = 1.0) {
    TriangleMesh m;
    const int segments = 2 * rings;
    auto add = [&](const glm::dvec3& unit) {
        m.positions.push_back(centre + radius * unit);
        m.normals.push_back(unit);
    };
    add({0, 1, 0});
    for (int i = 1; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const double theta = M_PI * i / rings, phi = 2.0 * M_PI * j / segments;
            add({std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
        }
    add({0, -1, 0});
    const auto south = static_cast<std::uint32_t>(m.positions.size() - 1);
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(1 + (i - 1) * segments + (j % segments)); };
    for (int j = 0; j < segments; ++j) {
        m.triangles.push_back({0, at(1, j + 1), at(1, j)});
        m.triangles.push_back({south, at(rings - 1, j), at(rings - 1, j + 1)});
    }
    for (int i = 1; i < rings - 1; ++i)
        for (int j = 0; j < segments; ++j) {
            m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    return m;
}

// An OBJ cube of half-size a about `centre`, six quads whose fronts face out (in, where
// `inward`); `flipped` (0-5) turns one face alone, `missing` leaves one out.
inline std::string cube_obj(const glm::dvec3& centre, double a, bool inward = false, int flipped = -1, int missing = -1) {
    std::string text;
    for (int i = 0; i < 8; ++i) {  // corner i: x from bit 2, y from bit 1, z from bit 0
        const glm::dvec3 p = centre + a * glm::dvec3(i & 4 ? 1 : -1, i & 2 ? 1 : -1, i & 1 ? 1 : -1);
        text += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    }
    // Counter-clockwise seen from outside: +x, -x, +y, -y, +z, -z.
    const int faces[6][4] = {{5, 7, 8, 6}, {1, 2, 4, 3}, {3, 4, 8, 7}, {1, 5, 6, 2}, {2, 6, 8, 4}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; ++f) {
        if (f == missing) continue;
        const bool reverse = inward != (f == flipped);
        text += "f";
        for (int k = 0; k < 4; ++k) text += " " + std::to_string(faces[f][reverse ? 3 - k : k]);
        text += "\n";
    }
    return text;
}

// A mesh as OBJ text: its vertices (shortest round-trip decimals), their normals where it has
// them, and its triangles.
inline std::string obj_text(const TriangleMesh& m) {
    std::string text;
    for (const glm::dvec3& p : m.positions) text += fmt::format("v {} {} {}\n", p.x, p.y, p.z);
    for (const glm::dvec3& n : m.normals) text += fmt::format("vn {} {} {}\n", n.x, n.y, n.z);
    const bool normals = m.normals.size() == m.positions.size();
    for (const auto& t : m.triangles) {
        text += "f";
        for (std::uint32_t v : t) text += normals ? fmt::format(" {0}//{0}", v + 1) : fmt::format(" {}", v + 1);
        text += "\n";
    }
    return text;
}

// The same cube as a closed Bezier surface, an object table's text: six flat bicubic patches,
// S_u x S_v out of the cube (in, where `inward`; `flipped` turns one face alone), and `extra`
// keys (a material) in the table.
inline std::string bezier_cube(const glm::dvec3& centre, double a, bool inward = false, int flipped = -1,
                               const std::string& extra = "") {
    const glm::dvec3 x(2 * a, 0, 0), y(0, 2 * a, 0), z(0, 0, 2 * a), lo = centre - glm::dvec3(a);
    const glm::dvec3 faces[6][3] = {{lo + x, y, z}, {lo, z, y}, {lo + y, z, x}, {lo, x, z}, {lo + z, x, y}, {lo, y, x}};
    std::string patches;
    for (int f = 0; f < 6; ++f) {
        glm::dvec3 u = faces[f][1], v = faces[f][2];
        if (inward != (f == flipped)) std::swap(u, v);
        patches += f ? ", [" : "[";
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                const glm::dvec3 p = faces[f][0] + u * (i / 3.0) + v * (j / 3.0);
                patches += fmt::format("{}[{}, {}, {}]", i + j ? ", " : "", p.x, p.y, p.z);  // shortest exact
            }
        patches += "]";
    }
    return "{ type = \"bezier\", closed = true, patches = [" + patches + "]" + (extra.empty() ? "" : ", " + extra) + " }";
}

}  // namespace lancer::test

// Ray/triangle mesh for the CPU reference: the mesh's own tree, then each candidate triangle by
// the watertight test of Woop, Benthin and Wald (JCGT 2013), in double. Twin of
// shaders/shapes/mesh.glsl (written apart: that one runs in float over the GPU's BVH).
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "cpu/shapes/element_walk.hpp"
#include "cpu/shapes/line_crossings.hpp"
#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

// The ray, sheared so that it runs along +z from the origin: a triangle is hit where the origin
// lies inside its projection, which three 2D edge functions decide. An edge shared by two
// triangles gives the same function (negated) in both, so no ray passes between them.
struct ShearedRay {
    dvec3 origin;
    int kx, ky, kz;
    double sx, sy, sz;

    explicit ShearedRay(const Ray& r) : origin(r.origin) {
        const dvec3 a = glm::abs(r.dir);
        kz = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        if (r.dir[kz] < 0.0) std::swap(kx, ky);  // keeps the winding
        sx = r.dir[kx] / r.dir[kz];
        sy = r.dir[ky] / r.dir[kz];
        sz = 1.0 / r.dir[kz];
    }
};

struct TriangleHit {
    double t, b1, b2;
};

// 2D edge function, exactly zero only where the origin is on the edge's line; there it is
// computed again in long double, as the paper does in double for float.
double edge(double ax, double ay, double bx, double by) {
    const double e = ax * by - ay * bx;
    if (e != 0.0) return e;
    return static_cast<double>(static_cast<long double>(ax) * by - static_cast<long double>(ay) * bx);
}

std::optional<TriangleHit> hit_triangle(const ShearedRay& r, const dvec3& v0, const dvec3& v1, const dvec3& v2,
                                        double t_min, double t_max) {
    const dvec3 a = v0 - r.origin, b = v1 - r.origin, c = v2 - r.origin;
    const double ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
    const double bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
    const double cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
    const double u = edge(cx, cy, bx, by);  // weight of v0
    const double v = edge(ax, ay, cx, cy);  // of v1
    const double w = edge(bx, by, ax, ay);  // of v2
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return std::nullopt;
    const double det = u + v + w;
    if (det == 0.0) return std::nullopt;  // edge-on
    const double t = (u * r.sz * a[r.kz] + v * r.sz * b[r.kz] + w * r.sz * c[r.kz]) / det;
    if (!(t > t_min && t < t_max)) return std::nullopt;
    return TriangleHit{t, v / det, w / det};
}

dvec3 object_normal(const TriangleMesh& mesh, std::uint32_t triangle) {
    const auto& t = mesh.triangles[triangle];
    return glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
}

}  // namespace

std::optional<SurfaceHit> intersect(const Mesh& m, const Ray& ray, double t_min, double t_max) {
    const TriangleMesh& mesh = m.geometry->mesh();
    const ShearedRay sheared(ray);
    std::optional<TriangleHit> best;
    std::uint32_t best_triangle = 0;
    double reach = t_max;
    walk_element_tree(m.geometry->tree(), ray, reach, [&](std::uint32_t i, double& reach) {
        const auto& tri = mesh.triangles[i];
        auto h = hit_triangle(sheared, mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]], t_min, reach);
        if (!h) return;
        best = h;
        best_triangle = i;
        reach = h->t;
    });
    if (!best) return std::nullopt;
    return SurfaceHit{best->t, glm::normalize(object_normal(mesh, best_triangle)), {best->b1, best->b2},
                      static_cast<int>(best_triangle)};
}

dvec3 mesh_shading_normal(const Mesh& m, const Placement& placed, int triangle, const glm::dvec2& b, const dvec3& facing) {
    const TriangleMesh& mesh = m.geometry->mesh();
    const auto& t = mesh.triangles[static_cast<std::size_t>(triangle)];
    const dvec3 n = (1.0 - b.x - b.y) * mesh.normals[t[0]] + b.x * mesh.normals[t[1]] + b.y * mesh.normals[t[2]];
    if (!(glm::length(n) > 0.0)) return facing;
    const dvec3 world = placed.world_normal(n);
    return glm::dot(world, facing) < 0.0 ? -world : world;
}

glm::dvec2 mesh_texture_uv(const Mesh& m, int triangle, const glm::dvec2& b) {
    const TriangleMesh& mesh = m.geometry->mesh();
    if (mesh.uvs.empty()) return b;
    const auto& t = mesh.triangles[static_cast<std::size_t>(triangle)];
    return (1.0 - b.x - b.y) * mesh.uvs[t[0]] + b.x * mesh.uvs[t[1]] + b.y * mesh.uvs[t[2]];
}

// The gap past each crossing skips the other triangle of an edge the ray passes through.
std::vector<LineCrossing> crossings_on_line(const Mesh& m, const Ray& ray, double t0, double t1) {
    const double gap = 1e-9 * glm::length(m.geometry->hi() - m.geometry->lo()) / glm::length(ray.dir);
    return crossings_by_search([&](double from, double to) { return intersect(m, ray, from, to); }, m.outward, ray, t0, t1, gap);
}

}  // namespace lancer::cpu

// Ray/axis-aligned box by the slab method. A ray from inside reports its exit point.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {

// The normal is the face of the slab that gave t, and (u, v) = (its axis, the normal's sign), as
// the shader's: at an edge, the face the ray crossed there.
std::optional<SurfaceHit> intersect(const Box& b, const Ray& ray, double t_min, double t_max) {
    double t_enter = -std::numeric_limits<double>::infinity();
    double t_exit = std::numeric_limits<double>::infinity();
    int enter_axis = 0, exit_axis = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (ray.dir[axis] == 0.0) {
            // Parallel to this slab: inside it for every t, or never.
            if (ray.origin[axis] < b.min[axis] || ray.origin[axis] > b.max[axis]) return std::nullopt;
            continue;
        }
        double t0 = (b.min[axis] - ray.origin[axis]) / ray.dir[axis];
        double t1 = (b.max[axis] - ray.origin[axis]) / ray.dir[axis];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > t_enter) {
            t_enter = t0;
            enter_axis = axis;
        }
        if (t1 < t_exit) {
            t_exit = t1;
            exit_axis = axis;
        }
    }
    if (t_enter > t_exit) return std::nullopt;
    double t, side;
    int axis;
    if (t_enter > t_min && t_enter < t_max) {
        t = t_enter, axis = enter_axis, side = -1.0;  // entering: the face turned toward the ray
    } else if (t_exit > t_min && t_exit < t_max) {
        t = t_exit, axis = exit_axis, side = 1.0;
    } else {
        return std::nullopt;
    }
    dvec3 n(0.0);
    n[axis] = ray.dir[axis] < 0.0 ? -side : side;
    return SurfaceHit{t, n, glm::dvec2(axis, n[axis])};
}

// Each face shows the whole image, upright as seen from outside: side faces with v up (+y), the
// top with v toward +z, the bottom with v toward -z (the table in docs/scene-format.md).
glm::dvec2 texture_uv(const Box& b, const dvec3& p, const dvec3& face_normal) {
    struct Direction {
        int axis;
        double sign;
    };
    // Fraction of the box's extent along a direction, 0 at the face it starts from.
    auto along = [&](Direction d) {
        double extent = b.max[d.axis] - b.min[d.axis];
        return d.sign > 0.0 ? (p[d.axis] - b.min[d.axis]) / extent : (b.max[d.axis] - p[d.axis]) / extent;
    };
    Direction u{0, 1.0}, v{1, 1.0};
    if (face_normal.x > 0.5) u = {2, 1.0};
    else if (face_normal.x < -0.5) u = {2, -1.0};
    else if (face_normal.z > 0.5) u = {0, -1.0};
    else if (face_normal.y > 0.5) v = {2, 1.0};
    else if (face_normal.y < -0.5) v = {2, -1.0};
    return {along(u), along(v)};
}

}  // namespace lancer::cpu

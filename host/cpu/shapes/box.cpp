// Ray/axis-aligned box by the slab method. A ray from inside reports its exit point.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>

#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

// The face whose plane the point is nearest, relative to the box's size.
dvec3 face_normal(const Box& b, const dvec3& p) {
    dvec3 center = 0.5 * (b.min + b.max);
    dvec3 half = 0.5 * (b.max - b.min);
    dvec3 d = (p - center) / half;
    dvec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) return {d.x < 0 ? -1.0 : 1.0, 0.0, 0.0};
    if (a.y >= a.z) return {0.0, d.y < 0 ? -1.0 : 1.0, 0.0};
    return {0.0, 0.0, d.z < 0 ? -1.0 : 1.0};
}

}  // namespace

std::optional<SurfaceHit> intersect(const Box& b, const Ray& ray, double t_min, double t_max) {
    double t_enter = -std::numeric_limits<double>::infinity();
    double t_exit = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (ray.dir[axis] == 0.0) {
            // Parallel to this slab: inside it for every t, or never.
            if (ray.origin[axis] < b.min[axis] || ray.origin[axis] > b.max[axis]) return std::nullopt;
            continue;
        }
        double t0 = (b.min[axis] - ray.origin[axis]) / ray.dir[axis];
        double t1 = (b.max[axis] - ray.origin[axis]) / ray.dir[axis];
        if (t0 > t1) std::swap(t0, t1);
        t_enter = std::max(t_enter, t0);
        t_exit = std::min(t_exit, t1);
    }
    if (t_enter > t_exit) return std::nullopt;
    double t;
    if (t_enter > t_min && t_enter < t_max) {
        t = t_enter;
    } else if (t_exit > t_min && t_exit < t_max) {
        t = t_exit;
    } else {
        return std::nullopt;
    }
    return SurfaceHit{t, face_normal(b, ray.origin + t * ray.dir)};
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

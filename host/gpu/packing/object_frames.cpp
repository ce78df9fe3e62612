#include "gpu/packing/object_frames.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace lancer::gpu {
namespace {

// Row r of affine map m (column-major: m[column][row]) as (linear row, translation).
vec4 row(const glm::dmat4& m, int r) { return vec4(float(m[0][r]), float(m[1][r]), float(m[2][r]), float(m[3][r])); }

}  // namespace

ObjectFrame object_frame(const Object& o, const dvec3& anchor) {
    const glm::dmat4 to_world = o.placement ? o.placement->to_world : glm::translate(glm::dmat4(1.0), -anchor);
    const glm::dmat4 to_object = o.placement ? o.placement->to_object : glm::translate(glm::dmat4(1.0), anchor);
    ObjectFrame f{};
    f.row0 = row(to_object, 0);
    f.row1 = row(to_object, 1);
    f.row2 = row(to_object, 2);
    f.world0 = row(to_world, 0);
    f.world1 = row(to_world, 1);
    f.world2 = row(to_world, 2);
    double stretch = 0.0;
    for (int r = 0; r < 3; ++r) stretch = std::max(stretch, std::abs(to_world[0][r]) + std::abs(to_world[1][r]) + std::abs(to_world[2][r]));
    // Rounded up: the error bounds it multiplies must not shrink.
    f.stretch = std::nextafter(float(stretch), INFINITY);
    f.mean_scale = float(std::cbrt(std::abs(glm::determinant(glm::dmat3(to_world)))));
    f.in_object_space = o.placement && o.placement->shape_in_object_space ? 1u : 0u;
    f.world = o.placement ? 0u : 1u;
    return f;
}

}  // namespace lancer::gpu

#pragma once
// Direction grids: the primitives of the BVH listed by the direction in which they are seen from
// one point, the eye or a point or spot light (Weghorst, Hooper and Greenberg's item buffer,
// Haines and Greenberg's light buffer). A camera ray starts at the eye, and a shadow ray's segment
// ends at its light, so the cell of its direction lists every primitive it can hit, nearest to
// the point first; the shader tests those instead of traversing the BVH (shaders/scene.glsl).
// On lavapipe a BVH traversal costs its SIMD group the longest of its lanes' walks; a cell's list
// is a few primitives, and neighbouring lanes read the same one (docs/performance.md).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/aabb.hpp"
#include "gpu/layout.hpp"

namespace lancer::gpu {

// grids[DIRECTION_GRID_EYE] is the eye's, grids[DIRECTION_GRID_LIGHT + k] light k's; a grid with
// valid == 0 sends its rays through the BVH.
struct DirectionGrids {
    std::vector<DirectionGrid> grids;
    std::vector<uint> cells;    // each grid's columns * rows + 1 starts into entries / 2
    std::vector<uint> entries;  // pairs: primitive index, float bits of its box's distance from the point
};

// The view the eye's grid covers: camera rays go along forward + x right + y up, |x|, |y| <= 1.
struct EyeView {
    glm::dvec3 eye;
    glm::dvec3 forward, right, up;  // forward a unit vector; right and up orthogonal to it, scaled
};

// A grid over the directions from `origin` in which the boxes (the BVH's primitives, in their
// packed order, with their indices) are seen. With `view`, only directions within it (the eye's
// grid: boxes behind the eye are left out, those around its plane are in every cell); without, the
// origin must be outside the boxes' bounds on one side of a plane through it, else the grid is not
// valid (a light among the primitives), and so is one whose cells would list too much, unless it
// is `required` (then only a grid that cannot be made is invalid: a view's never is).
// `slack`: how far (radians) a ray's direction may stray from the direction of its half-line.
DirectionGrid direction_grid(const glm::dvec3& origin, std::span<const Aabb> boxes, const EyeView* view, DirectionGrids& out,
                             double slack = 0.0, bool required = false);

// A flat mirror: a plane (as packed) that reflects camera rays. They then go along half-lines
// from the eye's mirror image, give or take the rounding of their start just off the plane.
struct Mirror {
    glm::dvec3 point, normal;  // normal: a unit vector
};

// An empty set of grids (all invalid), with room for the eye's, the mirror's and the lights'.
DirectionGrids no_grids();

// The grids of each point or spot light among the first (`lights`, as packed: their positions in
// the GPU's coordinates) over `boxes`, the BVH's primitives' boxes, added to `grids`.
void add_light_grids(std::span<const Light> lights, std::span<const Aabb> boxes, DirectionGrids& grids, bool required = false);

// The eye's grid, and the mirror's where there is one, added to `grids`.
void add_view_grids(const EyeView& view, const Mirror* mirror, std::span<const Aabb> boxes, DirectionGrids& grids,
                    bool required = false);

}  // namespace lancer::gpu

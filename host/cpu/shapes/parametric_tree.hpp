#pragma once
// The CPU reference's box hierarchy over a parametric surface's (u, v) domain: a binary tree of
// parameter rectangles, each with a box (in the surface's own frame) that contains the surface
// over it, by the natural interval extension. Built once per surface, on first use.
#include <vector>

#include <glm/mat4x4.hpp>

#include "surface/expr/program.hpp"
#include "surface/interval.hpp"
#include "surface/parametric_surface.hpp"

namespace lancer::cpu {

struct ParametricTreeNode {
    surface::Interval u, v;
    surface::dvec3 lo, hi;  // contains S(u, v) over the rectangle (local frame)
    int child[2] = {-1, -1};  // -1: none (a node may have one child where half is undefined)
    bool leaf() const { return child[0] < 0; }
};

struct ParametricTree {
    surface::Program program;  // x, y, z
    glm::dmat4 to_local{1.0};  // the inverse of the surface's to_world
    bool invertible = false;   // false for a singular to_world: such a surface is never hit
    std::vector<ParametricTreeNode> nodes;  // nodes[0] is the root (when there is one)
    double scale = 1.0;        // the local size of the surface, for tolerances

    // What the tree was built from, to catch a surface changed after its first use.
    double u0, u1, v0, v1;
    glm::dmat4 to_world;
};

ParametricTree build_parametric_tree(const surface::ParametricSurface& surface);

// The tree of a surface, built on its first use and kept in surface.derived.
const ParametricTree& parametric_tree(const surface::ParametricSurface& surface);

// How many parameter boxes this thread's last parametric intersect() examined (at most
// kMaxParametricBoxes), for tests and benchmarks of the search's effort.
int last_parametric_boxes();
inline constexpr int kMaxParametricBoxes = 4096;

}  // namespace lancer::cpu

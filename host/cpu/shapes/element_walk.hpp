#pragma once
// The walk through an element tree (host/mesh/element_tree.hpp) for the CPU reference: a mesh's
// triangles (mesh.cpp) and a sphere set's spheres (spheres.cpp), nearest boxes first.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "cpu/ray.hpp"
#include "mesh/element_tree.hpp"

namespace lancer::cpu {

// Entry distance of the ray into [lo, hi] before t_max, or nothing. The boxes hold their
// elements exactly, so a ray through a triangle's vertex passes through a box's corner, where the
// slabs' distances are equal but rounded apart: each exit is widened by its rounding (pbrt's
// 1 + 2 gamma(3), Ize 2013), so that such a ray is not turned away.
inline std::optional<double> box_entry(const dvec3& lo, const dvec3& hi, const Ray& r, const dvec3& inv, double t_max) {
    constexpr double kWiden = 1.0 + 8.0 * 0x1p-53;
    double enter = 0.0, leave = t_max;
    for (int k = 0; k < 3; ++k) {
        double t0 = (lo[k] - r.origin[k]) * inv[k], t1 = (hi[k] - r.origin[k]) * inv[k];
        if (std::isnan(t0) || std::isnan(t1)) continue;  // on a slab plane, parallel to it
        if (t0 > t1) std::swap(t0, t1);
        t1 *= kWiden;
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
    }
    if (enter > leave) return std::nullopt;
    return enter;
}

// Calls test(element, reach) for each element whose leaf box the ray enters before `reach`; the
// test lowers `reach` to its hit, so that farther boxes are skipped.
template <class Test>
void walk_element_tree(const ElementTree& tree, const Ray& ray, double& reach, Test&& test) {
    if (tree.nodes.empty()) return;
    const dvec3 inv = 1.0 / ray.dir;
    std::array<std::pair<std::uint32_t, double>, 64> stack;  // a median split's depth is about log2(n / 4) + 1
    std::size_t depth = 0;
    if (box_entry(tree.nodes[0].lo, tree.nodes[0].hi, ray, inv, reach)) stack[depth++] = {0u, 0.0};
    while (depth > 0) {
        auto [index, entry] = stack[--depth];
        if (entry > reach) continue;
        const ElementTree::Node& node = tree.nodes[index];
        if (node.count > 0) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) test(tree.order[i], reach);
            continue;
        }
        const ElementTree::Node &l = tree.nodes[node.first], &r = tree.nodes[node.first + 1];
        auto near_t = box_entry(l.lo, l.hi, ray, inv, reach), far_t = box_entry(r.lo, r.hi, ray, inv, reach);
        std::uint32_t near_child = node.first, far_child = node.first + 1;
        if (far_t && (!near_t || *far_t < *near_t)) {
            std::swap(near_t, far_t);
            std::swap(near_child, far_child);
        }
        if (far_t) stack[depth++] = {far_child, *far_t};
        if (near_t) stack[depth++] = {near_child, *near_t};
    }
}

}  // namespace lancer::cpu

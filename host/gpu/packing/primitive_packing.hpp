#pragma once
// Scene objects to the shader's primitives: one per sphere, plane, rectangle or box, one per
// Bezier leaf (each patch cut into 2^n x 2^n exact sub-patches), one per parametric cell, one
// per implicit surface; with the arrays their shapes index (patch leaves, surfaces and their
// cells, implicit surfaces), and each primitive's box where it is bounded. A new shape adds its
// case here (docs/adding-a-shape.md).
#include <cstdint>
#include <variant>
#include <vector>

#include "gpu/packing/family_boxes.hpp"
#include "gpu/packing/scene_packing.hpp"
#include "scene/scene.hpp"

namespace lancer::gpu {

// How spheres are packed: by centre and radius, or, where some sphere's centre is too far for
// float to place it within the picture's detail (a ground of radius 10^6), each by its point
// nearest `eye` (SPHERES_BY_NEAR_POINTS, shaders/shapes/sphere.glsl).
struct SpherePacking {
    bool by_near_points = false;
    dvec3 eye{0.0};
};
SpherePacking sphere_packing(const Scene& scene);

// The meshes and sphere sets that pack_object met, whose trees and elements pack_element_sets
// packs once the scene's primitives are planned: a renderer starts its pipeline from the
// features meanwhile (the bunny's tree takes about as long as the pipeline). Each placement is
// noted where it is its set's first or takes the file's materials, with its own copy of the
// shape (the geometry shared), so that the scene's objects may be freed first (PackOptions).
struct ElementSets {
    struct Placement {
        uint index;  // in PackedScene::meshes
        std::variant<Mesh, SphereSet> set;
        uint material;
        bool first;
    };
    ElementTreeCache* trees = nullptr;  // where given, the trees come from (and stay in) it
    std::vector<Placement> placements;
};

// Appends the primitives of scene object `object`, made of `material`, to `primitives`, and what
// they index to `out`'s arrays but for meshes' and sphere sets', which it notes in `sets`.
void pack_object(const Shape& shape, uint material, uint object, const SpherePacking& spheres, PackedScene& out,
                 std::vector<PrimitiveWithBox>& primitives, ElementSets& sets);

// Whether pack_object packs `o` alone into one primitive that indexes no array (the cheap shapes,
// unplaced, outside CSG): a still's objects of that kind can be packed from the last back and
// freed as they are (pack_scene).
bool packs_alone(const Object& o);

// The trees, elements and element materials of the sets noted in `sets`, into `out`.
void pack_element_sets(const ElementSets& sets, PackedScene& out);

// The Bezier leaves of the whole scene, counted before any is made: a scene with too many for
// the device is refused before the packer spends seconds and gigabytes on them.
std::uint64_t bezier_leaf_count(const Scene& scene);

}  // namespace lancer::gpu

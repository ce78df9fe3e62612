#pragma once
// How the tracer finds what a ray hits, planned in one place from the scene's primitives: which
// go into the BVH and in what order, which stay outside it (sorted by shape type, each family
// in a loop of its own, the cheap ones with boxes around them), the flat mirror, the direction
// grids, and the shader constants that follow (shaders/scene.glsl reads all of it).
//
// Per scene and per view apart: plan_scene depends on the objects, materials and lights, never
// on the camera, so a frame that only moves the camera keeps the scene's arrays and the
// pipeline; plan_view adds what the camera changes (the eye's grid and the mirror's). Where
// every ray takes a grid (grids_only, a per-scene decision), the view's grids are built whatever
// their cost, so that no camera can need the BVH's traversal the pipeline left out.
// Pure functions of their inputs; no Vulkan.
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "accel/bvh.hpp"
#include "gpu/layout.hpp"
#include "gpu/packing/direction_grids.hpp"
#include "gpu/packing/family_boxes.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace lancer::gpu {

// Whether rays take direction grids: where the scene allows them and they pay (Auto), never, or
// wherever the scene allows them, cost aside, with a BVH however few the primitives (Forced:
// tests prove that grids and the BVH find the same hits).
enum class GridUse { Auto, Never, Forced };

struct PlanOptions {
    Acceleration acceleration = Acceleration::Bvh;
    GridUse grids = GridUse::Auto;
    BvhCache* cache = nullptr;  // with one, a BVH over the same boxes as the last one is not built again
};

// The shader constants the plan decides (ShaderFeatures' members of the same names).
struct PlanFlags {
    uint scene_shapes = 0;
    bool has_bvh = false;
    bool bvh_has_analytic = false;  // a cheap bounded shape in the BVH
    uint boxed_families = 0, split_families = 0;
    bool direction_grids = false;
    bool grids_only = false;
};

struct AccelerationPlan {
    // The primitives in packed order: the BVH's in leaf order, then unbounded_count outside it,
    // sorted by shape type (each family split by its boxes' halves where it has two).
    std::vector<Primitive> primitives;
    uint unbounded_count = 0;
    std::vector<BvhNode> nodes;  // boxes rounded outward to float; empty without a BVH
    std::array<FamilyBoxes, SHAPE_COUNT> families{};
    uint mirror_plane = NO_PRIMITIVE;  // the plane whose reflections of camera rays take DIRECTION_GRID_MIRROR
    std::optional<Mirror> mirror;
    // The lights' grids (DIRECTION_GRID_LIGHT + k); the view's slots stay invalid until
    // plan_view. Their cells and entries come first, so the view's, which follow, change
    // nothing before them.
    DirectionGrids grids;
    std::vector<Aabb> grid_boxes;  // the BVH's primitives' boxes in packed order, for the view's grids
    bool view_grids_required = false;  // built whatever their cost (grids_only, or GridUse::Forced)
    PlanFlags flags;
};

struct PlanInput {
    std::vector<PrimitiveWithBox> primitives;      // in the scene's object order, boxes where bounded;
                                                   // taken, and freed as the plan is made
    std::span<const lancer::Material> materials;   // the scene's, which primitives index
    std::span<const gpu::Light> lights;            // as packed (the GPU's coordinates)
    bool photons = false;                          // photon mapping traces rays of its own, without grids
    std::span<const ObjectFrame> frames;           // by object, where objects are placed: a plane in its
                                                   // object's coordinates is no flat mirror to the plan
};

AccelerationPlan plan_scene(PlanInput input, const PlanOptions& options = {});

// The scene's grids with the view's added: the eye's, and the mirror's for the plan's mirror.
DirectionGrids plan_view(const AccelerationPlan& plan, const EyeView& view);

}  // namespace lancer::gpu

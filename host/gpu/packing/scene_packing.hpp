#pragma once
// Scene model -> the GPU's arrays (LANCER_SCENE_ARRAYS in shaders/layout.h): the primitives and
// what they index (primitive_packing), in the order the acceleration plan gives them with its
// BVH and direction grids (acceleration_plan), the materials and lights (material_packing); and
// which optional shader features the scene needs. Pure data conversion, no Vulkan.
#include <array>
#include <functional>
#include <map>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "accel/bvh.hpp"
#include "gpu/layout.hpp"
#include "gpu/packing/acceleration_plan.hpp"
#include "gpu/packing/family_boxes.hpp"
#include "gpu/vulkan/memory_budget.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace lancer::gpu {

struct PackedScene {
#define LANCER_PACKED_ARRAY(NAME, slot, kind, Element, member, reader, what) std::vector<Element> member;
    LANCER_SCENE_ARRAYS(LANCER_PACKED_ARRAY)
#undef LANCER_PACKED_ARRAY
    // Every position above is relative to this point, in double (gpu/packing/float_anchor.hpp).
    dvec3 anchor{0.0};
    // Objects the GPU's float cannot resolve at their distance from the anchor: for the notes.
    std::vector<std::string> float_notes;
    uint unbounded_count = 0;
    // The plane whose reflections of camera rays take the mirror's direction grid, or NO_PRIMITIVE.
    uint mirror_plane = NO_PRIMITIVE;
    // The sky's pattern in `patterns` (over directions: never moved by the anchor), or NO_MAP.
    uint sky_pattern = NO_MAP;
    // By shape type, the boxes around the families of cheap bounded shapes outside the BVH
    // (shape_is_boxable; the others have none: gpu/packing/family_boxes.hpp).
    std::array<FamilyBoxes, SHAPE_COUNT> families{};
    // The bytes at the end of grid_cells and grid_entries that depend on the camera (the eye's
    // and the mirror's grids): the rest of every array is the same for any camera.
    std::size_t view_grid_cells = 0, view_grid_entries = 0;
    uint photon_count = 0;  // photons per pass, with photon mapping
    // CSG leaves: packed by pack_object into csg_leaves, then stored at the end of primitives,
    // after every primitive the tracer traverses (csg_leaf_count of them). A leaf's `object` is
    // its frame: scene objects' frames come first, then the leaves' from csg_leaf_frames.
    // A surface of patches declared closed (SHAPE_ORIENTED) is one leaf whose pieces (cells,
    // sub-patches) follow its node's leaves, in runs of neighbours, each run after a primitive
    // with its box (p0, p1) and its length (data): the leaf's data = the first run's, p2.x = the
    // primitives of its runs (as a float: exact below 2^24), p2.y = its outward side (+-1), p0,
    // p1 = their box. A mesh leaf is its placement's primitive with p0.z = its outward side.
    std::vector<Primitive> csg_leaves;
    uint csg_leaf_frames = 0;
    uint csg_leaves_framed = 0;  // the leaves packed so far: the next one's frame is csg_leaf_frames + this
    std::size_t csg_leaf_count = 0;
    // Each mesh's and sphere set's index in `meshes`: packed once however many objects place it;
    // and for each of mesh_triangles and set_spheres, its triangle or sphere in the file.
    std::map<const void*, uint> mesh_indices;
    std::vector<std::uint32_t> mesh_order, set_order;
    // The scene's shape families and shading features: scene_shapes, has_bvh, has_textures, ...
    // (output_hits and check_loop_limit are the renderer's to set).
    ShaderFeatures features;

    std::size_t count(SceneArray array) const;
    std::span<const std::byte> bytes(SceneArray array) const;
    void release(SceneArray array);  // frees the array's memory (once the device holds a copy)
};

struct PackOptions {
    Acceleration acceleration = Acceleration::Bvh;
    GridUse grids = GridUse::Auto;
    BvhCache* cache = nullptr;  // with one, a BVH over the same boxes as the last one is not built again
    ElementTreeCache* element_trees = nullptr;  // with one, a mesh's or sphere set's tree is built once
    // When given, an array that would not fit the device is refused (UserError) before it is
    // filled: Bezier leaves multiply a scene's patches by up to 256.
    const DeviceMemoryLimits* limits = nullptr;
    // Called once the features are known, before the meshes' and sphere sets' trees are built.
    std::function<void(const ShaderFeatures&)> on_features;
    // The scene's objects, which the caller gives up: freed once packed, before the plan's
    // peak (10^6 spheres are 168 MiB of objects); the scene's other members are still read.
    std::vector<Object>* release_objects = nullptr;
};

PackedScene pack_scene(const Scene& scene, const PackOptions& options = {});
FrameParams pack_frame(const Scene& scene, const PackedScene& packed);

// What the packed scene's arrays need on the device, one entry per array.
std::vector<BufferNeed> scene_buffer_needs(const PackedScene& packed);

}  // namespace lancer::gpu

#include "gpu/packing/scene_packing.hpp"

#include <algorithm>
#include <bit>
#include <optional>
#include <stdexcept>

#include "core/page_release.hpp"
#include "scene/shape_bounds.hpp"

#include "gpu/packing/float_anchor.hpp"
#include "gpu/packing/float_bounds.hpp"
#include "gpu/packing/material_packing.hpp"
#include "gpu/packing/object_frames.hpp"
#include "gpu/packing/primitive_packing.hpp"
#include "scene/camera.hpp"

namespace lancer::gpu {

PackedScene pack_scene(const Scene& world, const PackOptions& options) {
    if (options.limits) check_buffer_need(array_need(SceneArray::PATCHES, bezier_leaf_count(world)), *options.limits);
    if (options.release_objects && options.release_objects != &world.objects)
        throw std::logic_error("pack_scene: release_objects must be the scene's own objects");
    PackedScene packed;
    packed.anchor = float_anchor(world.camera);
    packed.float_notes = float_resolution_notes(world, packed.anchor);
    std::optional<Scene> local;
    if (packed.anchor != dvec3(0.0)) local = rebased(world, packed.anchor);
    if (local && options.release_objects) std::vector<Object>().swap(*options.release_objects);  // the copy is packed
    const Scene& scene = local ? *local : world;
    std::vector<Object>* const release = options.release_objects ? (local ? &local->objects : options.release_objects) : nullptr;

    std::vector<PrimitiveWithBox> primitives;
    primitives.reserve(scene.objects.size());  // most objects are one primitive: no doubling's second array
    const SpherePacking spheres = sphere_packing(scene);
    bool placed = false, object_space = false;
    packed.csg_leaf_frames = static_cast<uint>(scene.objects.size());
    ElementSets sets{options.element_trees, {}};
    std::vector<const Object*> leaves;  // every CSG leaf, in the order their frames follow the objects'
    for (const Object& o : scene.objects)
        if (const auto* csg = std::get_if<Csg>(&o.shape))
            for (const Object& leaf : csg->leaves) {
                leaves.push_back(&leaf);
                placed |= leaf.placement.has_value();
                object_space |= leaf.placement && leaf.placement->shape_in_object_space;
            }
    if (release && std::all_of(scene.objects.begin(), scene.objects.end(), packs_alone)) {
        // Each packed alone into one primitive, from the last back, and freed as it is packed: the
        // objects and their primitives never coexist whole (10^6 spheres: 168 and 114 MiB).
        drain_from_back(*release, [&](const Object& o) {
            const auto i = static_cast<uint>(&o - release->data());
            const std::size_t before = primitives.size();
            pack_object(o.shape, o.material, i, spheres, packed, primitives, sets);
            if (primitives.size() != before + 1) throw std::logic_error("pack_scene: an object packed alone made other than one primitive");
        });
        std::reverse(primitives.begin(), primitives.end());  // in the objects' order
    }
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        placed |= o.placement.has_value();
        if (!o.placement || !o.placement->shape_in_object_space) {
            pack_object(o.shape, o.material, static_cast<uint>(i), spheres, packed, primitives, sets);
            continue;
        }
        // A shape in its own coordinates is packed there, by its point nearest the anchor there;
        // its primitives' boxes are the world's.
        object_space = true;
        const std::size_t first = primitives.size();
        pack_object(o.shape, o.material, static_cast<uint>(i), {spheres.by_near_points, o.placement->object_point(spheres.eye)},
                    packed, primitives, sets);
        for (std::size_t k = first; k < primitives.size(); ++k)
            if (primitives[k].second) primitives[k].second = object_bounds(o);
    }
    if (placed) {
        for (const Object& o : scene.objects) packed.object_frames.push_back(object_frame(o, packed.anchor));
        for (const Object* leaf : leaves) packed.object_frames.push_back(object_frame(*leaf, packed.anchor));
    }
    // With frames, patterns see the object's own coordinates, not the GPU's (the checker of an
    // object without a transform keeps its phase: placement.glsl).
    pack_materials(placed ? world : scene, packed.anchor, packed);
    for (const lancer::Light& l : scene.lights) packed.lights.push_back(pack_light(l));
    if (scene.photons) {
        pack_emitters(scene, packed);
        packed.photon_count = static_cast<uint>(scene.photons->count);
    }
    if (release) {  // nothing below reads them (the sets have their copies)
        leaves.clear();
        std::vector<Object>().swap(*release);
    }

    AccelerationPlan plan =
        plan_scene({std::move(primitives), scene.materials, packed.lights, scene.photons.has_value(), packed.object_frames},
                   {options.acceleration, options.grids, options.cache});
    // The eye as the shader has it (pack_frame), so that camera rays start at the grid's origin.
    const CameraBasis cam = make_camera_basis(scene.camera, scene.render.width, scene.render.height);
    const vec4 eye = v4(cam.eye);
    DirectionGrids grids = plan_view(plan, {dvec3(eye.x, eye.y, eye.z), cam.forward, cam.right, cam.up});
    packed.view_grid_cells = grids.cells.size() - plan.grids.cells.size();
    packed.view_grid_entries = grids.entries.size() - plan.grids.entries.size();
    if (plan.flags.direction_grids) {
        packed.grids = std::move(grids.grids);
        packed.grid_cells = std::move(grids.cells);
        packed.grid_entries = std::move(grids.entries);
    }
    packed.primitives = std::move(plan.primitives);
    // The CSG leaves after every primitive the tracer traverses (pack_frame's primitive_count).
    const auto leaves_start = static_cast<uint>(packed.primitives.size());
    for (CsgNode& node : packed.csg_nodes) {
        for (uint k = 0; k < node.leaf_count; ++k)
            if (Primitive& leaf = packed.csg_leaves[node.first_leaf + k]; shape_has(leaf.type, SHAPE_IN_PIECES)) leaf.data += leaves_start;
        node.first_leaf += leaves_start;
    }
    packed.primitives.insert(packed.primitives.end(), packed.csg_leaves.begin(), packed.csg_leaves.end());
    packed.csg_leaf_count = packed.csg_leaves.size();
    packed.unbounded_count = plan.unbounded_count;
    packed.nodes = std::move(plan.nodes);
    packed.families = plan.families;
    packed.mirror_plane = plan.mirror_plane;

    ShaderFeatures& f = packed.features;
    f.scene_shapes = plan.flags.scene_shapes;
    f.csg_leaf_shapes = 0;
    for (const Primitive& leaf : packed.csg_leaves) {
        f.scene_shapes |= 1u << leaf.type;
        f.csg_leaf_shapes |= 1u << leaf.type;
    }
    f.leaf_only_shapes = f.csg_leaf_shapes & ~plan.flags.scene_shapes;
    f.lathe_degrees = 0;
    for (const Primitive& p : packed.primitives)
        if (p.type == SHAPE_LATHE) f.lathe_degrees |= 1u << static_cast<uint>(p.p0.w);
    f.has_bvh = plan.flags.has_bvh;
    f.bvh_has_analytic = plan.flags.bvh_has_analytic;
    f.boxed_families = plan.flags.boxed_families;
    f.split_families = plan.flags.split_families;
    f.direction_grids = plan.flags.direction_grids;
    f.grids_only = plan.flags.grids_only;
    f.has_photons = scene.photons.has_value();
    f.has_fog = scene.fog.has_value();
    f.has_sky = scene.sky.has_value();
    f.sky_has_pattern = scene.sky && scene.sky->pattern;
    f.spheres_by_near_points = spheres.by_near_points && f.has_shape(SHAPE_SPHERE);
    f.placed_objects = placed;
    f.object_space_shapes = object_space;
    for (const PatchLeaf& leaf : packed.patches)
        for (const vec4& point : leaf.points) f.has_rational_patches |= point.w != 1.0f;
    f.has_textures = !packed.textures.empty();
    f.has_patterns = !packed.patterns.empty();
    for (const lancer::Material& m : scene.materials) {
        f.has_transparency |= m.transparent();
        f.has_blinn |= m.highlight == Highlight::Blinn;
        f.has_microfacet |= m.microfacet();
    }
    for (const lancer::Light& l : scene.lights) {
        f.has_area_lights |= l.type == LightType::Area;
        f.has_spot_lights |= l.type == LightType::Spot;
        f.has_falloff |= l.falloff != Falloff::None;
    }
    // The features are whole: the renderer's pipeline builds while the sets' trees do.
    if (options.on_features) options.on_features(packed.features);
    pack_element_sets(sets, packed);
    if (options.element_trees) options.element_trees->prune();  // the sets of earlier scenes let go
    return packed;
}

std::size_t PackedScene::count(SceneArray array) const {
    switch (array) {
#define LANCER_PACKED_COUNT(NAME, slot, kind, Element, member, reader, what) \
    case SceneArray::NAME: return member.size();
        LANCER_SCENE_ARRAYS(LANCER_PACKED_COUNT)
#undef LANCER_PACKED_COUNT
    }
    return 0;
}

std::span<const std::byte> PackedScene::bytes(SceneArray array) const {
    switch (array) {
#define LANCER_PACKED_BYTES(NAME, slot, kind, Element, member, reader, what) \
    case SceneArray::NAME: return std::as_bytes(std::span(member));
        LANCER_SCENE_ARRAYS(LANCER_PACKED_BYTES)
#undef LANCER_PACKED_BYTES
    }
    return {};
}

void PackedScene::release(SceneArray array) {
    switch (array) {
#define LANCER_PACKED_RELEASE(NAME, slot, kind, Element, member, reader, what) \
    case SceneArray::NAME: std::vector<Element>().swap(member); return;
        LANCER_SCENE_ARRAYS(LANCER_PACKED_RELEASE)
#undef LANCER_PACKED_RELEASE
    }
}

std::vector<BufferNeed> scene_buffer_needs(const PackedScene& packed) {
    std::vector<BufferNeed> needs;
    for (std::size_t a = 0; a < kSceneArrayCount; ++a) needs.push_back(array_need(SceneArray(a), packed.count(SceneArray(a))));
    return needs;
}

FrameParams pack_frame(const Scene& scene, const PackedScene& packed) {
    const RenderSettings& r = scene.render;
    CameraBasis cam = make_camera_basis(scene.camera, r.width, r.height);
    FrameParams f{};
    f.eye = v4(cam.eye - packed.anchor);
    f.forward = v4(cam.forward);
    f.right = v4(cam.right);
    f.up = v4(cam.up);
    f.background = v4(r.background);
    f.ambient = v4(scene.ambient);
    if (scene.fog) f.fog = v4(scene.fog->color, 1.0 / scene.fog->distance);
    if (scene.fog && scene.fog->ground) {  // heights in the GPU's frame, which starts at the anchor
        const Fog::Ground& g = *scene.fog->ground;
        f.fog_ground = v4(g.up / g.altitude, (g.offset - glm::dot(packed.anchor, g.up)) / g.altitude);
    }
    if (scene.sky) {
        f.sky_colors = static_cast<uint>(scene.sky->colors.size());
        f.sky_pattern = packed.sky_pattern;
        for (std::size_t i = 0; i < scene.sky->colors.size(); ++i) f.sky[i] = v4(scene.sky->colors[i].color, scene.sky->colors[i].position);
    }
    f.width = static_cast<uint>(r.width);
    f.height = static_cast<uint>(r.height);
    f.samples = static_cast<uint>(r.samples);
    f.max_depth = static_cast<uint>(r.max_depth);
    const std::size_t traversed = packed.primitives.size() - packed.csg_leaf_count;  // the CSG leaves follow
    f.primitive_count = static_cast<uint>(traversed);
    f.light_count = static_cast<uint>(packed.lights.size());
    f.node_count = static_cast<uint>(packed.nodes.size());
    f.unbounded_count = packed.unbounded_count;
    // Where each family of the unbounded primitives (sorted by type) ends, and the family boxes
    // (family_boxes.hpp): two per family, the second unused unless it is split.
    std::size_t i = traversed - packed.unbounded_count;
    for (uint type = 0; type < SHAPE_COUNT; ++type) {
        const uint begin = static_cast<uint>(i);
        while (i < traversed && packed.primitives[i].type <= type) ++i;
        f.family_end[type / 4][type % 4] = static_cast<uint>(i);
        f.family_split[type / 4][type % 4] = begin + packed.families[type].split_at;
        for (int h = 0; h < 2; ++h) {
            const Aabb& box = packed.families[type].halves[h];
            pack_box(box.empty() ? Aabb{dvec3(0.0), dvec3(0.0)} : box, f.family_lo[2 * type + h], f.family_hi[2 * type + h]);
        }
    }
    f.mirror_plane = packed.mirror_plane;
    f.loop_probe = 2;
    return f;
}

}  // namespace lancer::gpu

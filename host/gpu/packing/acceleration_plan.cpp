#include "gpu/packing/acceleration_plan.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

#include "core/page_release.hpp"
#include "gpu/packing/float_bounds.hpp"

namespace lancer::gpu {
namespace {

// With this few bounded primitives, testing them all beats traversing a tree (measured on
// lavapipe: the BVH loop's stack and divergence cost more than a handful of sphere tests).
constexpr std::size_t kMinPrimitivesForBvh = 16;
// But two shapes that are costly to test and tightly boxed pay for a tree already: outside one,
// every ray runs each one's whole test, masked where it misses its box (bench/extrusions.toml 0.42
// of the time). Those are prisms and text, lathes, sors, blobs, superellipsoids, meshes and sphere
// sets, and cheap shapes kept in their own coordinates, whose test carries the ray there first
// (scenes/transforms.toml 0.58 at 1280x720). Not counted: CSG objects, tori and implicit
// surfaces, whose scenes ran as fast or slower in a tree (scenes/lens.toml 1.07, tori.toml 1.0,
// implicit.toml 1.05), its traversal making their pipelines slower to create (docs/performance.md).
constexpr std::size_t kMinCostlyForBvh = 2;

bool costly_in_a_tree(const Primitive& p, std::span<const ObjectFrame> frames) {
    if (shape_has(p.type, SHAPE_CHEAP)) return !frames.empty() && frames[p.object].in_object_space != 0;
    return p.type != SHAPE_CSG && p.type != SHAPE_TORUS && p.type != SHAPE_IMPLICIT;
}

// At most this many cheap bounded shapes stay outside a BVH of costly ones.
constexpr std::size_t kMaxAnalyticOutsideBvh = 8;

// Beside costly shapes (patches, expression surfaces) in a BVH, a few cheap bounded ones stay
// outside it, tested by every ray in loops of their own: in the BVH's leaves, lavapipe would run
// their code at every test of a patch or cell (the teapot 0.93x the time).
bool cheap_ones_stay_outside(std::span<const PrimitiveWithBox> primitives) {
    std::size_t analytic = 0;
    bool costly = false;
    for (const auto& [p, box] : primitives) {
        if (!box) continue;
        analytic += shape_is_boxable(p.type);
        costly |= !shape_has(p.type, SHAPE_CHEAP);
    }
    return costly && analytic <= kMaxAnalyticOutsideBvh;
}

// The first plane that is a flat mirror (its reflections of camera rays are camera rays of the
// eye's mirror image): packed index and plane, or none.
std::optional<Mirror> find_mirror(const AccelerationPlan& plan, std::span<const lancer::Material> materials,
                                  std::span<const ObjectFrame> frames, uint& index) {
    for (std::size_t i = plan.primitives.size() - plan.unbounded_count; i < plan.primitives.size(); ++i) {
        const Primitive& p = plan.primitives[i];
        const lancer::Material& m = materials[p.material];
        if (p.type != SHAPE_PLANE || !(m.reflection > 0.0) || m.microfacet() || m.bump) continue;
        if (!frames.empty() && frames[p.object].in_object_space) continue;
        index = static_cast<uint>(i);
        return Mirror{dvec3(p.p0.x, p.p0.y, p.p0.z), glm::normalize(dvec3(p.p1.x, p.p1.y, p.p1.z))};
    }
    return std::nullopt;
}

// Whether every ray the tracer spawns can take a grid, so that the BVH's traversal can be left
// out of the pipeline: camera rays (the eye's grid), their reflections in the flat mirror (the
// mirror's), shadow rays to point and spot lights (each light's). That holds where no other
// surface spawns rays (the one predicate both renderers share:
// Material::spawns_secondary_rays), every light has a grid, and photon mapping, which traces
// rays of its own, is off.
bool every_ray_takes_a_grid(const AccelerationPlan& plan, const PlanInput& input) {
    if (input.photons || input.lights.size() > DIRECTION_GRID_COUNT - DIRECTION_GRID_LIGHT) return false;
    for (std::size_t k = 0; k < input.lights.size(); ++k)
        if (!plan.grids.grids[DIRECTION_GRID_LIGHT + k].valid) return false;
    for (std::size_t i = 0; i < plan.primitives.size(); ++i)
        if (i != plan.mirror_plane && input.materials[plan.primitives[i].material].spawns_secondary_rays()) return false;
    return true;
}

// primitives[i] becomes the old primitives[order[i]] (order: a permutation), in place: the
// primitives are the plan's largest array, and a second one would double it.
void put_in_leaf_order(std::vector<Primitive>& primitives, std::span<const std::uint32_t> order) {
    std::vector<bool> placed(order.size());
    for (std::size_t start = 0; start < order.size(); ++start) {
        if (placed[start]) continue;
        const Primitive first = primitives[start];
        std::size_t i = start;
        for (; order[i] != start; i = order[i]) {
            primitives[i] = primitives[order[i]];
            placed[i] = true;
        }
        primitives[i] = first;
        placed[i] = true;
    }
}

}  // namespace

AccelerationPlan plan_scene(PlanInput input, const PlanOptions& options) {
    AccelerationPlan plan;
    PlanFlags& f = plan.flags;
    std::size_t bounded_count = 0, costly_count = 0;
    Aabb everything;
    for (const auto& [p, box] : input.primitives) {
        bounded_count += box.has_value();
        costly_count += box.has_value() && costly_in_a_tree(p, input.frames);
        f.scene_shapes |= 1u << p.type;
        if (box) everything.extend(*box);
    }
    const Acceleration acceleration = options.acceleration;
    const bool enough = bounded_count >= kMinPrimitivesForBvh || costly_count >= kMinCostlyForBvh;
    const bool use_bvh = acceleration == Acceleration::BvhAlways ||
                         (acceleration == Acceleration::Bvh && (enough || (options.grids == GridUse::Forced && bounded_count > 0)));
    const bool analytic_outside = cheap_ones_stay_outside(input.primitives);
    // The BVH's primitives (then put in its leaf order, to become plan.primitives) and boxes apart
    // from the others, the scene's pairs freed behind them: each array is held once.
    std::vector<Primitive> bounded;
    std::vector<Aabb> boxes;
    std::vector<PrimitiveWithBox> unbounded;
    if (use_bvh) {
        bounded.reserve(input.primitives.size());  // the unbounded ones follow it in plan.primitives
        boxes.reserve(bounded_count);
    }
    drain(input.primitives, [&](const PrimitiveWithBox& e) {
        if (use_bvh && e.second && !(analytic_outside && shape_is_boxable(e.first.type))) {
            bounded.push_back(e.first);
            boxes.push_back(*e.second);
        } else {
            unbounded.push_back(e);
        }
    });
    bool cheap_tree = true;
    for (const Primitive& p : bounded) cheap_tree &= shape_has(p.type, SHAPE_CHEAP);
    std::shared_ptr<const Bvh> cached;
    Bvh built;
    if (options.cache) {
        cached = options.cache->build(boxes, tree_options(bounded.size(), cheap_tree));
        plan.grid_boxes.reserve(cached->order.size());
        for (std::uint32_t index : cached->order) plan.grid_boxes.push_back(boxes[index]);
        std::vector<Aabb>().swap(boxes);  // freed before the direction grids are built
    } else {
        built = build_bvh_from(std::move(boxes), tree_options(bounded.size(), cheap_tree), &plan.grid_boxes);
    }
    const Bvh& bvh = cached ? *cached : built;
    put_in_leaf_order(bounded, bvh.order);
    plan.primitives = std::move(bounded);
    plan.nodes.reserve(bvh.nodes.size());
    auto pack_node = [&](const lancer::BvhNode& n) {
        BvhNode g{};
        pack_box(n.box, g.lo, g.hi);
        g.first = n.first;
        g.count = n.count;
        plan.nodes.push_back(g);
    };
    if (cached) {
        for (const lancer::BvhNode& n : cached->nodes) pack_node(n);
        cached.reset();
    } else {
        drain(built.nodes, pack_node);
        built = {};
    }
    f.has_bvh = !plan.nodes.empty();
    for (const Primitive& p : plan.primitives) f.bvh_has_analytic |= shape_is_boxable(p.type);

    // By family, so that the shader tests each family in a loop of its own (scene.glsl), with a
    // box around each family of cheap bounded shapes where it pays (family_boxes.hpp).
    std::stable_sort(unbounded.begin(), unbounded.end(), [](const auto& a, const auto& b) { return a.first.type < b.first.type; });
    for (uint type = 0; type < SHAPE_COUNT; ++type) {
        if (!shape_is_boxable(type)) continue;
        auto begin = std::find_if(unbounded.begin(), unbounded.end(), [&](const auto& e) { return e.first.type == type; });
        auto end = std::find_if(begin, unbounded.end(), [&](const auto& e) { return e.first.type != type; });
        plan.families[type] = box_family(std::span(begin, end), everything);
        if (plan.families[type].boxed) f.boxed_families |= 1u << type;
        if (plan.families[type].split) f.split_families |= 1u << type;
    }
    plan.primitives.reserve(plan.primitives.size() + unbounded.size());
    for (const auto& e : unbounded) plan.primitives.push_back(e.first);
    plan.unbounded_count = static_cast<uint>(unbounded.size());

    // Direction grids for camera and shadow rays, where every shape is cheap to test (the
    // shader's CHEAP_SHAPES) and any hit blocks a shadow ray (no transparency).
    plan.grids = no_grids();
    bool cheap = true, transparency = false;
    for (const Primitive& p : plan.primitives) cheap &= shape_has(p.type, SHAPE_CHEAP);
    for (const lancer::Material& m : input.materials) transparency |= m.transparent();
    f.direction_grids = options.grids != GridUse::Never && f.has_bvh && cheap && !transparency;
    if (!f.direction_grids) return plan;
    plan.mirror = find_mirror(plan, input.materials, input.frames, plan.mirror_plane);
    add_light_grids(input.lights, plan.grid_boxes, plan.grids, options.grids == GridUse::Forced);
    f.grids_only = every_ray_takes_a_grid(plan, input);
    plan.view_grids_required = f.grids_only || options.grids == GridUse::Forced;
    return plan;
}

DirectionGrids plan_view(const AccelerationPlan& plan, const EyeView& view) {
    DirectionGrids grids = plan.grids;
    if (plan.flags.direction_grids)
        add_view_grids(view, plan.mirror ? &*plan.mirror : nullptr, plan.grid_boxes, grids, plan.view_grids_required);
    return grids;
}

}  // namespace lancer::gpu

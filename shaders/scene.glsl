// Scene buffers and the query every ray needs: the nearest hit, or any hit for shadow rays
// (trace_scene; dielectric.glsl's transmittance traces shadow rays). Bounded primitives are
// found through the BVH; the rest (planes, and a few analytic shapes beside patches or
// expression surfaces: BVH_HAS_ANALYTIC) are tested by every ray, family by family.
#ifndef LANCER_SCENE_GLSL
#define LANCER_SCENE_GLSL

#include "interface.glsl"
#include "placement.glsl"

#include "shapes/sphere.glsl"
#include "shapes/plane.glsl"
#include "shapes/rectangle.glsl"
#include "shapes/disc.glsl"
#include "shapes/cone.glsl"
#include "shapes/torus.glsl"
#include "shapes/box.glsl"
#include "shapes/element_tree.glsl"
#include "shapes/mesh.glsl"
#include "shapes/spheres.glsl"
#include "polynomial.glsl"
#include "shapes/blob.glsl"
#include "shapes/sor.glsl"
#include "shapes/prism.glsl"
#include "shapes/lathe.glsl"
#include "shapes/superellipsoid.glsl"
#include "shapes/bezier.glsl"
#include "surface_functions.glsl"  // the scene's expression surfaces, generated (host/gpu/shaders/surface_codegen.cpp)
#include "shapes/parametric.glsl"
#include "shapes/implicit.glsl"

// The shape table's traits (shapes.h), as conditions on its constant traits. Written without
// && and || between constants: glslang gives a negated short-circuit over specialisation
// constants an operand SPIRV-Tools cannot fold (tests/unit/spirv_cache_test.cpp).
#define LANCER_BOUNDED(traits) (((traits) & SHAPE_BOUNDED) != 0u)
#define LANCER_BOXABLE(traits) (((traits) & (SHAPE_BOUNDED | SHAPE_CHEAP)) == (SHAPE_BOUNDED | SHAPE_CHEAP))
// Whether a shape of the family can be in the BVH: bounded, and where it is cheap, only where
// the host put cheap shapes there (BVH_HAS_ANALYTIC).
#define LANCER_MAY_BE_IN_BVH(traits) (LANCER_BOUNDED(traits) && (!LANCER_BOXABLE(traits) || BVH_HAS_ANALYTIC))
// Whether it can be outside the BVH, tested by every ray in its family's loop.
#define LANCER_MAY_BE_OUTSIDE_BVH(traits) (!SCENE_HAS_BVH || !LANCER_BOUNDED(traits) || (LANCER_BOXABLE(traits) && !BVH_HAS_ANALYTIC))

// A CSG leaf's hit in (t_min, t_max): its intersection through its placement (the solids' and
// closed shapes' only: csg.glsl, which follows, never calls itself).
#define LANCER_LEAF_CASE(NAME, name, Type, type, traits)                                     \
    case SHAPE_##NAME:                                                                        \
        hit = CSG_HAS_##NAME && ((traits) & families) != 0u &&                                \
              name##_intersect(p, ray, t_min * k, t_max * k, t_hit, uv, error);                \
        break;
// CSG is no solid: its row of the switch calls this instead of itself (GLSL has no recursion).
bool csg_is_no_leaf(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    return false;
}
#define csg_intersect csg_is_no_leaf
bool leaf_hit(Primitive p, Ray world_ray, float t_min, float t_max, uint families, out float t_hit, out vec2 uv, out float error) {
    uv = vec2(0.0);
    error = 0.0;
    float k;
    Ray ray = primitive_ray(p, world_ray, k);
    bool hit = false;
    switch (p.type) {
        LANCER_SHAPES(LANCER_LEAF_CASE)
    }
    if (OBJECT_SPACE_SHAPES) t_hit = t_hit / k;
    return hit;
}
#undef LANCER_LEAF_CASE
#undef csg_intersect

// Whether a walked CSG leaf (SHAPE_CLOSED: the torus, the blob, the sor, the prism, the lathe and the implicit surfaces, as the CPU
// reference's cpu/shapes/csg.cpp asserts) holds the world ray's point at t.
bool leaf_inside(Primitive p, Ray world_ray, float t) {
    float k;
    Ray ray = primitive_ray(p, world_ray, k);
    vec3 point = ray.origin + (t * k) * ray.dir;
    if (p.type == SHAPE_TORUS) return CSG_HAS_TORUS && torus_inside(p, point);
    if (p.type == SHAPE_BLOB) return CSG_HAS_BLOB && blob_inside(p, point);
    if (p.type == SHAPE_SOR) return CSG_HAS_SOR && sor_inside(p, point);
    if (p.type == SHAPE_PRISM) return CSG_HAS_PRISM && prism_inside(p, point);
    if (p.type == SHAPE_LATHE) return CSG_HAS_LATHE && lathe_inside(p, point);
    if (p.type == SHAPE_IMPLICIT) return CSG_HAS_IMPLICIT && implicit_inside(p, point);
    return false;
}

// Whether the world ray enters a walked CSG leaf's solid at its root t (uv: leaf_hit's there): 1
// where its outward normal faces the ray, 0 where it faces away, -1 where the ray grazes it or
// the family's normals are not known to face out (the implicit surfaces). Not asked of the torus:
// its walk went slower for it (scenes/cutaway.toml; docs/performance.md).
int leaf_root_side(Primitive p, Ray world_ray, float t, vec2 uv) {
    float k, error;
    Ray ray = primitive_ray(p, world_ray, k);
    t *= k;
    vec3 point = ray.origin + t * ray.dir, n = vec3(0.0);
    if (p.type == SHAPE_BLOB) n = CSG_HAS_BLOB ? blob_hit_normal(p, ray, t, point, uv, error) : n;
    if (p.type == SHAPE_SOR) n = CSG_HAS_SOR ? sor_hit_normal(p, ray, t, point, uv, error) : n;
    if (p.type == SHAPE_PRISM) n = CSG_HAS_PRISM ? prism_hit_normal(p, ray, t, point, uv, error) : n;
    if (p.type == SHAPE_LATHE) n = CSG_HAS_LATHE ? lathe_hit_normal(p, ray, t, point, uv, error) : n;
    float along = dot(n, ray.dir);
    if (!(abs(along) > 1e-3 * length(ray.dir))) return -1;
    return along < 0.0 ? 1 : 0;
}

#include "shapes/csg.glsl"

// uv: the surface's own parameters at the hit, for shapes that have them; error: the error bound
// of a Bezier or implicit hit, which only their search knows (primitive_normal completes the
// others'). Only families the scene has are compiled in (lavapipe runs every case of a switch,
// the type being known only at run time); `bounded` (a constant: p is in the BVH) leaves out the
// families never in it (LANCER_MAY_BE_IN_BVH).
// A shape kept in its object's coordinates is tested there (placement.glsl).
#define LANCER_INTERSECT_CASE(NAME, name, Type, type, traits)                                   \
    case SHAPE_##NAME:                                                                              \
        hit = TRACES_##NAME && (!bounded || LANCER_MAY_BE_IN_BVH(traits)) &&                  \
              name##_intersect(p, ray, t_min * k, t_max * k, t_hit, uv, error);                   \
        break;
bool shape_intersect(uint type, Primitive p, Ray world_ray, float t_min, float t_max, bool bounded, out float t_hit, out vec2 uv,
                     out float error) {
    uv = vec2(0.0);
    error = 0.0;
    float k;
    Ray ray = primitive_ray(p, world_ray, k);
    bool hit = false;
    switch (type) {
        LANCER_SHAPES(LANCER_INTERSECT_CASE)
    }
    if (OBJECT_SPACE_SHAPES) t_hit = min(t_hit / k, t_max);
    return hit;
}

// The unit normal at a hit on primitive `index` at t (p: the point there as the caller computed
// it), and the hit's error bound (Hit.error): `error` comes in as the search found it (Bezier,
// implicit) and goes out complete: the analytic and parametric shapes' computed from the hit
// (here once per ray, not for every candidate hit of the search), implicit surfaces' plus the
// band their enclosures cannot resolve, from the gradient at p. One switch, one fetch of the
// primitive.
#define LANCER_NORMAL_CASE(NAME, name, Type, type, traits) \
    case SHAPE_##NAME:                                          \
        if (SCENE_HAS_##NAME) return name##_hit_normal(prim, ray, t, p, uv, error); \
        break;
vec3 shape_normal(Primitive prim, Ray ray, float t, vec3 p, vec2 uv, inout float error) {
    switch (prim.type) {
        LANCER_SHAPES(LANCER_NORMAL_CASE)
    }
    return vec3(0.0, 0.0, 1.0);
}

// A shape kept in its object's coordinates gives its normal and error bound there, at the hit
// point as it found it (an edge's face is then the one its intersection chose): the normal is
// carried back as a gradient; the bound grows by the map's stretch, after the rounding of p's
// own map into the object (p is what the caller will use).
vec3 primitive_normal(uint index, Ray ray, float t, vec3 p, vec2 uv, inout float error) {
    Primitive prim = primitive_at(index);
    if (OBJECT_SPACE_SHAPES) {
        ObjectFrame f = object_frame_at(prim.object);
        if (f.in_object_space != 0u) {
            float k;
            Ray local = object_ray(f, ray, k);
            float s = t * k;
            vec3 n = shape_normal(prim, local, s, local.origin + s * local.dir, uv, error);
            error = f.stretch * (error + object_point_rounding(f, p)) + hit_point_rounding(ray.origin, t);
            return unit_vector(world_gradient(f, n));
        }
    }
    return shape_normal(prim, ray, t, p, uv, error);
}

// The origin of a ray going on through primitive `prim` at p (past_surface): a mesh's facet meets
// neighbours that turn at its edges, which a grazing ray carried along its line could pass to
// their far side; there it starts straight across (its path through a medium longer by at most
// the offset). Twin of host/cpu/dielectric.cpp's.
vec3 through_surface(uint prim, vec3 p, vec3 n, vec3 d, float error) {
    if (SCENE_HAS_MESH && primitive_at(prim).type == SHAPE_MESH) return offset_origin(p, dot(d, n) < 0.0 ? -n : n, error);
    return past_surface(p, n, d, error);
}

const int BVH_STACK_SIZE = 64;  // the builder bounds the tree depth by 60 (host/accel/bvh.cpp)

// Two hits this close are one point found twice (neighbouring patch leaves and parametric cells
// share their edges): within their searches' error bounds of each other, or 1e-6 of t for the
// rounding of roots found to float's noise. The primitive with the smaller stable key wins, so
// the answer does not depend on the order primitives are tested in (BVH or brute force give
// identical images). Two sheets of a surface further apart are two hits: the nearer is drawn.
const float TIE = 1e-6;

// Object index and shape data: the same whichever order the primitives are stored in.
uvec2 stable_key(Primitive p) { return uvec2(p.object, p.data); }

struct Nearest {
    float t;  // nearest hit so far, or t_max
    uint prim;
    vec2 uv;
    float error;  // a Bezier or implicit hit's error bound, as its search found it (primitive_normal completes it)
};

// How far a test must look: up to t_max, or a little past the best hit to see its ties.
float reach(Nearest best) { return best.prim == NO_PRIMITIVE ? best.t : best.t * (1.0 + TIE) + 2.0 * best.error; }

// Primitive i, which is p, hit at t: kept if it is nearer than the best hit (or an equally
// near, smaller-keyed twin).
bool keep_if_nearer(uint i, Primitive p, float t, vec2 uv, float error, inout Nearest best) {
    if (best.prim != NO_PRIMITIVE && t >= best.t - (TIE * best.t + error + best.error)) {
        uvec2 a = stable_key(p), b = stable_key(primitive_at(best.prim));
        if (!(a.x < b.x || (a.x == b.x && a.y < b.y))) return false;
    }
    // An equally near twin keeps the nearer t: where that is the other's, so is its error bound.
    best = Nearest(min(t, best.t), i, uv, t < best.t ? error : max(error, best.error));
    return true;
}

// Tests primitive i, which is p, in a BVH leaf or a grid's cell (bounded: its box is known to be
// entered) or as a shadow hint. A shadow ray's (any_hit): whether p is hit before best.t, which
// it then becomes (no ties to settle: the first hit ends the search). Any other ray's: whether p
// is hit nearer than the best hit, or is an equally near, smaller-keyed twin, and then kept. One
// call of shape_intersect for both: lavapipe inlines each call, with every shape's code.
bool test_primitive(uint i, Primitive p, Ray ray, float t_min, bool bounded, bool any_hit, inout Nearest best) {
    float t, error;
    vec2 uv;
    if (!shape_intersect(p.type, p, ray, t_min, any_hit ? best.t : reach(best), bounded, t, uv, error)) return false;
    if (!any_hit) return keep_if_nearer(i, p, t, uv, error, best);
    best = Nearest(t, i, uv, error);
    return true;
}

// The primitives outside the BVH (with a BVH, the unbounded ones, and the cheap bounded ones
// where BVH_HAS_ANALYTIC is false; without one, all of them) are sorted by family
// (host/gpu/packing/scene_packing.cpp), and each family is tested in a loop of its own that calls its
// intersection directly: lavapipe would otherwise run every family's code for every primitive
// (docs/performance.md).
// Not through shape_intersect with a constant type: lavapipe inlines the whole switch at each
// of the loops before it folds it, and took 0.4 s longer to create the pipeline.
uint family_end(uint type) { return frame.family_end[type / 4u][type % 4u]; }
uint family_begin(uint type) { return type == 0u ? frame.primitive_count - frame.unbounded_count : family_end(type - 1u); }
uint family_split(uint type) { return frame.family_split[type / 4u][type % 4u]; }

// The family boxes (host/gpu/packing/family_boxes.hpp): where a family of several cheap bounded shapes
// is outside the BVH, the host puts a box around it (<NAME>_BOXED: family_lo/hi[2 type]), or,
// for five or more, around each of its two halves (<NAME>_SPLIT: [2 type] the members before
// `family_split(type)`, [2 type + 1] the rest), rounded outward like the BVH's. A ray that
// misses a box skips its members: lavapipe runs an `if`'s body for every SIMD lane whatever the
// condition, and saves work only where a loop runs fewer times (docs/performance.md).
bool enters_family_box(uint box, Ray ray, float limit) {
    return box_entry(frame.family_lo[box].xyz, frame.family_hi[box].xyz, ray.origin, safe_inverse(ray.dir), limit) != INFINITY;
}

// One family's loop, for each row of the shape table: its intersection tests p against the ray
// up to LANCER_LOOP_LIMIT, setting t (and uv, error where the family has them);
// LANCER_ON_HIT then uses the hit (both defined around each use). The conditions on the
// specialisation constants and the constant traits alone are ones the host removes
// (spirv_specialize.hpp) where they are false.
#define LANCER_FAMILY_LOOP(NAME, name, Type, type, traits)                                          \
    if (TRACES_##NAME && LANCER_MAY_BE_OUTSIDE_BVH(traits)) {                                      \
        uint first = family_begin(SHAPE_##NAME), last = family_end(SHAPE_##NAME);                            \
        if (LANCER_BOXABLE(traits) && NAME##_BOXED) {                                              \
            float box_limit = LANCER_LOOP_LIMIT;                                                   \
            if (NAME##_SPLIT) {                                                                    \
                uint split = family_split(SHAPE_##NAME);                                                \
                if (!enters_family_box(2u * SHAPE_##NAME, ray, box_limit)) first = split;               \
                if (!enters_family_box(2u * SHAPE_##NAME + 1u, ray, box_limit)) last = split;           \
            } else if (!enters_family_box(2u * SHAPE_##NAME, ray, box_limit)) {                         \
                last = first;                                                                      \
            }                                                                                      \
        }                                                                                          \
        for (uint i = first; i < last; ++i) {                                                      \
            Primitive p = primitive_at(i);                                                         \
            float limit = LANCER_LOOP_LIMIT;                                                       \
            float t, error = 0.0, k;                                                               \
            vec2 uv = vec2(0.0);                                                                   \
            Ray shape_ray = primitive_ray(p, ray, k);                                              \
            if (name##_intersect(p, shape_ray, t_min * k, limit * k, t, uv, error)) {               \
                if (OBJECT_SPACE_SHAPES) t = min(t / k, limit);                                    \
                LANCER_ON_HIT                                                                      \
            }                                                                                      \
        }                                                                                          \
    }

// The primitives outside the BVH: the nearest hit, or with any_hit whether there is one.
#define LANCER_LOOP_LIMIT reach(best)
#define LANCER_ON_HIT \
    if (keep_if_nearer(i, p, t, uv, error, best) && any_hit) return true;
bool unbounded_hit(Ray ray, float t_min, bool any_hit, inout Nearest best) {
    LANCER_SHAPES(LANCER_FAMILY_LOOP)
    return false;
}
#undef LANCER_LOOP_LIMIT
#undef LANCER_ON_HIT

// Where every shape of the scene is cheap to test, shadow rays take a lean path through the
// primitives outside the BVH (lean_unbounded_hit). Scenes with Bezier patches or expression
// surfaces keep the one path: lavapipe's code for their searches is slower beside a second one
// (docs/performance.md).
#define LANCER_COSTLY_BIT(NAME, name, Type, type, traits) | ((((traits) & SHAPE_CHEAP) != 0u) ? 0u : (1u << SHAPE_##NAME))
const uint COSTLY_SHAPES = 0u LANCER_SHAPES(LANCER_COSTLY_BIT);
const bool CHEAP_SHAPES = (SCENE_SHAPES & (COSTLY_SHAPES & BUILT_SHAPES)) == 0u;

// Shadow hints: a shadow ray first tests the primitive that blocked the last shadow ray to the
// same light (dielectric.glsl's shadow_blockers), which saves the BVH traversal wherever it still
// blocks. Only with a BVH: without one the extra test costs more than it saves (docs/performance.md).
const bool SHADOW_HINTS = CHEAP_SHAPES && SCENE_HAS_BVH;

// unbounded_hit for a shadow ray, with the hint (any primitive, or NO_PRIMITIVE) first and
// without the nearest hit's bookkeeping.
#define LANCER_LOOP_LIMIT best.t
#define LANCER_ON_HIT                    \
    {                                    \
        best = Nearest(t, i, uv, error); \
        return true;                     \
    }
bool lean_unbounded_hit(Ray ray, float t_min, uint hint, inout Nearest best) {
    if (SHADOW_HINTS && hint != NO_PRIMITIVE) {
        Primitive p = primitive_at(hint);
        if (test_primitive(hint, p, ray, t_min, false, true, best)) return true;
    }
    LANCER_SHAPES(LANCER_FAMILY_LOOP)
    return false;
}
#undef LANCER_LOOP_LIMIT
#undef LANCER_ON_HIT

// A camera ray, its reflection in a flat mirror or a shadow ray through direction grid g
// (layout.h's DirectionGrid) instead of the BVH: a camera ray starts at the grid's origin, the
// eye, and goes along ray.dir; a reflection goes along ray.dir on a half-line from the eye's
// mirror image (the host's grid allows for its start just off the mirror); a shadow ray's segment
// ends at its light, the grid's origin, so it lies along ray.origin - origin. The cell of that
// direction lists every primitive of the BVH the ray can hit, nearest to the origin first: the
// search ends at the first farther from the origin than the ray's start plus the best hit, or
// than a shadow ray's start.
bool grid_hit(DirectionGrid g, Ray ray, float t_min, bool any_hit, inout Nearest best) {
    vec3 w = any_hit ? ray.origin - g.origin.xyz : ray.dir;
    float z = dot(w, g.axis.xyz);
    vec2 c = (vec2(dot(w, g.across_u.xyz), dot(w, g.across_v.xyz)) / z - g.window.xy) * g.window.zw;
    uint first = 0u, last = 0u;
    if (z > 0.0 && c.x >= 0.0 && c.y >= 0.0 && c.x < float(g.columns) && c.y < float(g.rows)) {
        uint cell = g.first_cell + uint(c.y) * g.columns + uint(c.x);
        first = grid_cell_at(cell);
        last = grid_cell_at(cell + 1u);
    }
    float start = length(ray.origin - g.origin.xyz);  // 0 for a camera ray
    for (uint e = first; e < last; ++e) {
        if (uintBitsToFloat(grid_entry_at(2u * e + 1u)) > (any_hit ? start : start + reach(best))) break;
        uint i = grid_entry_at(2u * e);
        Primitive p = primitive_at(i);
        if (test_primitive(i, p, ray, t_min, true, any_hit, best) && any_hit) return true;
    }
    return best.prim != NO_PRIMITIVE;
}

// Set where a ray without a grid met a pipeline without the BVH's traversal (GRIDS_ONLY): the
// host's plan and the shader's rays disagree (gpu/packing/acceleration_plan.hpp). Tests run
// with CHECK_GRID_CONTRACT, and the invocation then marks its pixel (trace.comp).
bool grid_contract_broken = false;

// Nearest hit in (t_min, t_max) over all primitives; with any_hit, the first hit found, and
// primitive `hint` tested first (NO_PRIMITIVE: none; see SHADOW_HINTS). `grid`: the direction
// grid the ray may take instead of the BVH (DIRECTION_GRID_EYE for camera rays,
// DIRECTION_GRID_MIRROR for their reflections in the flat mirror, DIRECTION_GRID_LIGHT + k for
// shadow rays to light k), or NO_GRID (never where GRIDS_ONLY).
bool trace_scene(Ray ray, float t_min, float t_max, bool any_hit, uint hint, uint grid, out Nearest best) {
    shadow_ray_any_hit = any_hit;
    best = Nearest(t_max, NO_PRIMITIVE, vec2(0.0), 0.0);
    // The branch on CHEAP_SHAPES alone, a specialisation constant, is one the host removes
    // (spirv_specialize.hpp) before lavapipe sees the module.
    bool found;
    if (CHEAP_SHAPES) {
        found = any_hit ? lean_unbounded_hit(ray, t_min, hint, best) : unbounded_hit(ray, t_min, false, best);
    } else {
        found = unbounded_hit(ray, t_min, any_hit, best);
    }
    if (found) return true;
    if (!SCENE_HAS_BVH || frame.node_count == 0u) return best.prim != NO_PRIMITIVE;
    // Conditions on the constants alone: the host removes them where false. Where the host found
    // that every ray of the scene takes a grid (GRIDS_ONLY), the traversal below is dead code,
    // which lavapipe would otherwise pay for in every call, taken or not.
    if (DIRECTION_GRIDS) {
        if (GRIDS_ONLY) {
            if (CHECK_GRID_CONTRACT && grid == NO_GRID) grid_contract_broken = true;
            return grid_hit(grid_at(grid), ray, t_min, any_hit, best);
        }
        if (grid != NO_GRID && grid_at(grid).valid != 0u) return grid_hit(grid_at(grid), ray, t_min, any_hit, best);
    }

    vec3 inv_dir = safe_inverse(ray.dir);
    uint stack[BVH_STACK_SIZE];
    float stack_t[BVH_STACK_SIZE];
    int sp = 0;
    uint node = 0u;
    if (box_entry(node_at(0).lo.xyz, node_at(0).hi.xyz, ray.origin, inv_dir, reach(best)) == INFINITY) {
        return best.prim != NO_PRIMITIVE;
    }
    // "While-while" traversal (Aila and Laine 2009): interior nodes in one loop, until a leaf;
    // the leaf's primitives after it. lavapipe runs every path that any lane of a SIMD group
    // takes, so one loop doing both would pay for a leaf's tests (Bezier clipping, Newton) in
    // every step where some lane is at a leaf: the teapot took 1.5 times as long.
    bool visit = true;  // `node` is next; else the next is popped from the stack
    for (;;) {
        BvhNode n;
        for (;;) {
            if (!visit) {
                // Pop the next subtree that may still hold something as near as the best hit.
                bool found = false;
                while (sp > 0) {
                    --sp;
                    // A shadow ray's limit never changes: what it pushed, it still has to visit.
                    if (any_hit || stack_t[sp] <= reach(best)) {
                        node = stack[sp];
                        found = true;
                        break;
                    }
                }
                if (!found) return best.prim != NO_PRIMITIVE;
            }
            n = node_at(node);
            if (n.count > 0u) break;
            uint near_child = n.first;
            uint far_child = n.first + 1u;
            float limit = reach(best);
            vec3 lo_a = node_at(near_child).lo.xyz, hi_a = node_at(near_child).hi.xyz;
            vec3 lo_b = node_at(far_child).lo.xyz, hi_b = node_at(far_child).hi.xyz;
            float t_near = box_entry(lo_a, hi_a, ray.origin, inv_dir, limit);
            float t_far = box_entry(lo_b, hi_b, ray.origin, inv_dir, limit);
            // The child whose centre comes first along the ray first, rather than the one whose
            // box the ray enters first: rays of neighbouring pixels then agree on the order, and
            // a SIMD group's lanes stay on one path. Which hit is nearest does not depend on the
            // order (ties go by key).
            if (dot((lo_b + hi_b) - (lo_a + hi_a), ray.dir) < 0.0) {
                uint c = near_child; near_child = far_child; far_child = c;
                float f = t_near; t_near = t_far; t_far = f;
            }
            if (t_near == INFINITY) {  // the ray misses the first: the second alone, if it enters it
                near_child = far_child;
                t_near = t_far;
                t_far = INFINITY;
            }
            visit = t_near != INFINITY;
            if (visit) {
                if (t_far != INFINITY) {
                    stack[sp] = far_child;
                    if (!any_hit) stack_t[sp] = t_far;
                    ++sp;
                }
                node = near_child;
            }
        }
        for (uint i = n.first; i < n.first + n.count; ++i) {
            Primitive p = primitive_at(i);
            if (CHEAP_SHAPES) {
                if (test_primitive(i, p, ray, t_min, true, any_hit, best) && any_hit) return true;
            } else if (test_primitive(i, p, ray, t_min, true, false, best) && any_hit) {
                return true;
            }
        }
        visit = false;
    }
    return best.prim != NO_PRIMITIVE;
}

bool closest_hit(Ray ray, float t_min, uint grid, out Hit hit) {
    Nearest best;
    if (!trace_scene(ray, t_min, INFINITY, false, NO_PRIMITIVE, grid, best)) return false;
    hit.t = best.t;
    hit.primitive = best.prim;
    hit.uv = best.uv;
    hit.error = best.error;
    // A CSG hit is its leaf's: shaded with the leaf's normal, material and texture.
    if (SCENE_HAS_CSG && primitive_at(best.prim).type == SHAPE_CSG)
        hit.primitive = csg_leaf_hit(primitive_at(best.prim), ray, best.t, best.uv, hit.uv, hit.error);
    hit.normal = primitive_normal(hit.primitive, ray, best.t, ray.origin + best.t * ray.dir, hit.uv, hit.error);
    return true;
}

// The material at a hit on primitive `prim` with parameters uv (Hit.uv): its primitive's, or a
// mesh triangle's or a set sphere's own.
uint hit_material(uint prim, vec2 uv) {
    Primitive p = primitive_at(prim);
    if ((SCENE_HAS_MESH && p.type == SHAPE_MESH) || (SCENE_HAS_SPHERES && p.type == SHAPE_SPHERES)) return element_hit_material(p, uv);
    return p.material;
}

// The hit's parameters on its whole surface (a Bezier leaf's are mapped to its patch's).
vec2 surface_uv(Hit hit) {
    Primitive prim = primitive_at(hit.primitive);
    if (SCENE_HAS_BEZIER && prim.type == SHAPE_BEZIER) {
        vec4 dom = patch_leaf_at(prim.data).domain;
        return vec2(mix(dom.x, dom.y, hit.uv.x), mix(dom.z, dom.w, hit.uv.y));
    }
    return hit.uv;
}

// Which patch of a Bezier surface was hit (-1 for other shapes).
float surface_part(Hit hit) {
    Primitive prim = primitive_at(hit.primitive);
    if (SCENE_HAS_BEZIER && prim.type == SHAPE_BEZIER) return patch_leaf_at(prim.data).origin.w;
    return -1.0;
}

#endif

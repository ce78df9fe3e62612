// CSG: POV-Ray's intersection, difference and merge (scene/scene.hpp's Csg). Twin of
// host/cpu/shapes/csg.cpp, written apart. p0, p1 = the combination's box (xyz), data = its
// CsgNode. Its convex leaves (SHAPE_SOLID: convex solids and half-spaces) are each inside along
// the ray on one interval: from their first hit from -infinity to the reversed ray's (a
// half-space's reaches to infinity). Its closed leaves that are not convex (SHAPE_CLOSED: tori,
// implicit surfaces) are walked root by root from t_min (or from where the combination's value
// depends on them again: csg_moot_until), each stretch between roots told by f's sign at its
// middle (leaf_inside), adjacent stretches inside joined; so are the surfaces that close a solid
// (SHAPE_ORIENTED: closed meshes, Bezier and parametric surfaces declared closed), from the
// line's start, each stretch inside where the ray entered at its start, by the normal's side
// there (csg_crossing). A walked leaf holds one interval at a time, the next found once the ray
// passes its end; an interval the ray enters is held open, its end found only once the ray
// passes its entry (csg_walk). The combination's surface
// is the first end of an interval, beyond t_min, where the program's value changes: comparing
// ends, not counting crossings, stays exact where a ray grazes a leaf (an interval of no length
// changes nothing). A hit is the leaf's: uv = (the leaf's primitive, 0 at a convex leaf's
// entry, 1 at its exit, 2 at a walked leaf's root), which closest_hit resolves (csg_leaf_hit) so
// that the leaf's normal, material and texture shade it.
#ifndef LANCER_CSG_GLSL
#define LANCER_CSG_GLSL

const uint CSG_MAX_ENDS = 256u;  // interval ends examined per ray: beyond, a miss
const int CSG_WALK_ROOTS = 32;   // roots one walk examines

// The walked leaf's root at the last CSG hit returned on one (leaf primitive, t, its uv), and its
// error: closest_hit's csg_leaf_hit takes them from here instead of searching the root again. A
// later CSG test may overwrite it (a tie not kept): csg_leaf_hit then finds the key differs.
vec4 csg_walked_root = vec4(-1.0);
float csg_walked_root_error = 0.0;

// Scenes without a shape CSG walks (SHAPE_CLOSED, SHAPE_ORIENTED) compile no walk: one test of
// the constant shape set (|| between specialisation constants would leave SPIRV-Tools an operand
// it cannot fold).
#define LANCER_WALKABLE_BIT(NAME, name, Type, type, traits) | ((((traits) & (SHAPE_CLOSED | SHAPE_ORIENTED)) != 0u) ? 1u << (type) : 0u)
const uint CSG_WALKABLE = 0u LANCER_SHAPES(LANCER_WALKABLE_BIT);
#undef LANCER_WALKABLE_BIT
const bool CSG_MAY_WALK = (CSG_LEAF_SHAPES & (CSG_WALKABLE & BUILT_SHAPES)) != 0u;
bool csg_walked(Primitive leaf) { return CSG_MAY_WALK && (shape_traits(leaf.type) & (SHAPE_CLOSED | SHAPE_ORIENTED)) != 0u; }
bool csg_crossed(Primitive leaf) { return CSG_MAY_WALK && (shape_traits(leaf.type) & SHAPE_ORIENTED) != 0u; }

// A piece (parametric cell, Bezier sub-patch) of a surface leaf: its nearest hit in (t_min, t_max),
// for shadow rays too (CSG needs every crossing in order).
bool csg_piece_hit(Primitive q, Ray ray, float t_min, float t_max, out float t, out vec2 uv, out float error) {
    error = 0.0;
    uv = vec2(0.0);
    if (CSG_HAS_PARAMETRIC && q.type == SHAPE_PARAMETRIC) return parametric_search(q, ray, t_min, t_max, false, t, uv, error);
    if (CSG_HAS_BEZIER && q.type == SHAPE_BEZIER) return bezier_search(q, ray, t_min, t_max, false, t, uv, error);
    return false;
}

// A surface that closes a solid (SHAPE_ORIENTED: a Bezier or parametric surface packed as its
// pieces after its node's leaves, or a mesh: scene_packing.hpp): its nearest crossing with t in
// (t_min, t_max), which piece (NO_PRIMITIVE: a mesh's own; uv then holds its triangle), and
// whether the ray leaves the solid there (its normal, turned by the outward side, along it).
bool csg_crossing(Primitive leaf, Ray world_ray, float t_min, float t_max, out float t_hit, out vec2 uv, out float error,
                  out uint piece, out bool leaving) {
    float k;
    Ray ray = primitive_ray(leaf, world_ray, k);
    piece = NO_PRIMITIVE;
    leaving = false;
    error = 0.0;
    uv = vec2(0.0);
    // The searches take t >= 0 only, and CSG asks along the whole line: from the line's entry
    // into the surface's box, then, as origin.
    bool mesh = CSG_HAS_MESH && leaf.type == SHAPE_MESH;
    vec3 lo = leaf.p0.xyz, hi = leaf.p1.xyz;
    if (mesh) {
        MeshNode root = mesh_node_at(mesh_at(leaf.data).first_node);
        lo = root.lo.xyz;
        hi = root.hi.xyz;
    }
    vec3 t0 = (lo - ray.origin) * safe_inverse(ray.dir), t1 = (hi - ray.origin) * safe_inverse(ray.dir);
    vec3 near = min(t0, t1), far = max(t0, t1);
    float line_in = max(max(near.x, near.y), near.z), line_out = min(min(far.x, far.y), far.z);
    if (!(line_in <= line_out && line_out > t_min * k && line_in < t_max * k)) return false;
    ray.origin += line_in * ray.dir;
    t_hit = min(t_max * k, line_out) - line_in;
    float t_low = max(t_min * k - line_in, 0.0);
    vec3 n;
    if (mesh) {
        float t;
        // The nearest crossing, even for a shadow ray: it opens or closes the leaf's interval.
        if (!element_set_intersect(leaf, false, false, ray, t_low, t_hit, t, uv)) return false;
        float normal_error;
        n = mesh_hit_normal(leaf, ray, t, ray.origin + t * ray.dir, uv, normal_error);
        leaving = leaf.p0.z * dot(n, ray.dir) > 0.0;
        t_hit = (t + line_in) / k;
        return true;
    }
    uint end = leaf.data + uint(leaf.p2.x);
    vec3 inv_dir = safe_inverse(ray.dir);
    for (uint run = leaf.data; run < end; run += primitive_at(run).data + 1u) {
        Primitive head = primitive_at(run);  // the run's box and length (scene_packing.hpp)
        if (box_entry(head.p0.xyz, head.p1.xyz, ray.origin, inv_dir, t_hit) == INFINITY) continue;
        for (uint i = run + 1u; i <= run + head.data; ++i) {
            float t, e;
            vec2 q_uv;
            Primitive q = primitive_at(i);
            if (box_entry(q.p0.xyz, q.p1.xyz, ray.origin, inv_dir, t_hit) == INFINITY) continue;  // most pieces
            if (csg_piece_hit(q, ray, t_low, t_hit, t, q_uv, e)) {
                t_hit = t;
                uv = q_uv;
                error = e;
                piece = i;
            }
        }
    }
    if (piece == NO_PRIMITIVE) return false;
    float normal_error;
    Primitive q = primitive_at(piece);
    vec3 p = ray.origin + t_hit * ray.dir;
    n = q.type == SHAPE_PARAMETRIC ? parametric_hit_normal(q, ray, t_hit, p, uv, normal_error)
                                        : bezier_hit_normal(q, ray, t_hit, p, uv, normal_error);
    leaving = leaf.p2.y * dot(n, ray.dir) > 0.0;
    t_hit = (t_hit + line_in) / k;
    return true;
}

// Past a root at a, a walked leaf's next search starts this far on: its searches are
// not deterministic in t_min (the torus re-bases its segment there), so from a itself one could
// find a again. 4e-6 of the node's box: beyond the searches' resolution (the torus's 6e-8 of its
// ball, the implicit surfaces' 1e-6 of their boxes), and beyond float's at a.
float csg_walk_gap(Primitive node, float a) { return max(4e-6 * length(node.p1.xyz - node.p0.xyz), 5e-7 * abs(a)); }

// A walked leaf's first interval inside that ends after `after`, walking on from its interval
// `now` (empty: afresh from `from`; opened: from its start); empty where none. An
// interval whose entry the leaf's normal vouches for (leaf_root_side, csg_crossing) is returned
// opened, (entry, INFINITY), its end found only if the combination's surface is not at its entry
// (csg_intersect): most rays stop there, one search instead of three. A stretch is inside by
// leaf_inside at its middle; a normal only ever decides the stretch it opens or closes, so that a
// ray grazing a corner, whose second root lies within the gap, cannot carry a wrong side on.
// ends_uv and ends_error: the leaf's uv and error at the interval's ends that are roots (in:
// `now`'s, out: the interval returned's).
vec2 csg_walk(Primitive node, Primitive leaf, Ray ray, vec2 now, float after, float from, inout vec4 ends_uv,
              inout vec2 ends_error) {
    vec2 span = vec2(INFINITY, -INFINITY);
    bool opened = now.y == INFINITY;
    // A walk begun afresh starts at `from` (the ray's t_min, or where the leaf begins to matter
    // again: csg_moot_until), not at the line's start: the roots before it (a shadow ray's own
    // surface) are not searched, and its first stretch is told by its middle as any other; where
    // inside, it is held from `after` (the leaf did not matter before `from`: no end there). A
    // surface that closes a solid is told by its crossings: from the line's start.
    bool from_point = !(now.x < now.y) && from > -INFINITY && !csg_crossed(leaf);
    float a = opened ? now.x : (now.x < now.y ? now.y : (from_point ? from : -INFINITY));
    bool entered = opened;  // a surface that closes a solid: inside after a, where the ray entered it at a
    vec2 uv_a = opened ? ends_uv.xy : ends_uv.zw;  // the leaf's at the root a
    float error_a = opened ? ends_error.x : ends_error.y;
    for (int i = 0; i < CSG_WALK_ROOTS; ++i) {
        float b, error;
        vec2 uv;
        float start = a == -INFINITY || from_point ? a : a + csg_walk_gap(node, a);
        bool more, leaving = false;
        uint piece;
        if (csg_crossed(leaf)) more = csg_crossing(leaf, ray, start, INFINITY, b, uv, error, piece, leaving);
        else more = leaf_hit(leaf, ray, start, INFINITY, SHAPE_CLOSED, b, uv, error);
        bool inside = csg_crossed(leaf) ? entered : a != -INFINITY && leaf_inside(leaf, ray, 0.5 * (a + b));
        entered = !leaving;
        int side = !more ? -1 : (csg_crossed(leaf) ? (leaving ? 0 : 1) : leaf_root_side(leaf, ray, b, uv));
        if (more && inside) {
            if (!(span.x < span.y)) {
                ends_uv.xy = uv_a;
                ends_error.x = error_a;
            }
            span = span.x < span.y ? vec2(span.x, b) : vec2(from_point ? after : a, b);  // adjacent stretches inside join
            ends_uv.zw = uv;
            ends_error.y = error;
            if (side == 0) {  // left
                if (b > after) break;
                span = vec2(INFINITY, -INFINITY);
            }
        } else if (span.x < span.y) {
            if (span.y > after) break;
            span = vec2(INFINITY, -INFINITY);
        }
        from_point = false;
        if (!more) break;
        if (side == 1 && !(span.x < span.y) && b > after) {
            ends_uv.xy = uv;
            ends_error.x = error;
            span = vec2(b, INFINITY);
            break;
        }
        a = b;
        uv_a = uv;
        error_a = error;
    }
    return span;
}

// A convex leaf's inside along the ray: (in, out), empty where in >= out.
vec2 csg_inside(Primitive leaf, Ray ray) {
    float error;
    vec2 uv;
    if (leaf.type == SHAPE_PLANE) {
        // The half-space behind the normal, in the plane's own coordinates (t is the same there).
        float k;
        Ray r = primitive_ray(leaf, ray, k);
        float along = dot(r.dir, leaf.p1.xyz), height = dot(r.origin - leaf.p0.xyz, leaf.p1.xyz);
        if (along == 0.0) return height < 0.0 ? vec2(-INFINITY, INFINITY) : vec2(INFINITY, -INFINITY);
        float t = -height / along / k;
        return along > 0.0 ? vec2(-INFINITY, t) : vec2(t, INFINITY);
    }
    // The exit is the reversed ray's entry: no second search from the entry, whose rounding
    // could find the entry again or step past a close exit. One call in a loop: lavapipe inlines
    // each call, and two would double every solid's code in the pipeline.
    vec2 ends;
    for (int side = 0; side < 2; ++side) {
        float t;
        if (!leaf_hit(leaf, Ray(ray.origin, side == 0 ? ray.dir : -ray.dir), -INFINITY, INFINITY, SHAPE_SOLID, t, uv, error))
            return vec2(INFINITY, -INFINITY);
        ends[side] = t;
    }
    return vec2(ends.x, -ends.y);  // in >= out: a touching ray, no length
}

// The program's value with every leaf's inside as just before t (after = false) or after it.
bool csg_value(CsgNode node, vec2 inside[CSG_MAX_LEAVES], float t, bool after) {
    uint stack = 0u;
    for (uint i = 0u; i < node.op_count; ++i) {
        uint op = csg_op_at(node.first_op + i), kind = op & 15u;
        if (kind == CSG_LEAF) {
            vec2 span = inside[op >> 4u];
            bool inside_it = after ? (span.x <= t && t < span.y) : (span.x < t && t <= span.y);
            stack = (stack << 1u) | (inside_it ? 1u : 0u);
        } else if (kind == CSG_NOT) {
            stack ^= 1u;
        } else {
            uint b = stack & 1u, a = (stack >> 1u) & 1u;
            uint c = kind == CSG_AND ? (a & b) : (kind == CSG_OR ? (a | b) : (a & (b ^ 1u)));
            stack = ((stack >> 2u) << 1u) | c;
        }
    }
    return (stack & 1u) != 0u;
}

// Whether the program's value just after t changes with leaf k's inside (the others' as they are).
bool csg_depends_on(CsgNode node, vec2 inside[CSG_MAX_LEAVES], uint k, float t) {
    uint with = 0u, without = 0u;  // the stacks with leaf k inside and outside
    for (uint i = 0u; i < node.op_count; ++i) {
        uint op = csg_op_at(node.first_op + i), kind = op & 15u;
        if (kind == CSG_LEAF) {
            vec2 span = inside[op >> 4u];
            uint v = span.x <= t && t < span.y ? 1u : 0u;
            bool it = (op >> 4u) == k;
            with = (with << 1u) | (it ? 1u : v);
            without = (without << 1u) | (it ? 0u : v);
        } else if (kind == CSG_NOT) {
            with ^= 1u;
            without ^= 1u;
        } else {
            uvec2 b = uvec2(with, without) & 1u, a = (uvec2(with, without) >> 1u) & 1u;
            uvec2 c = kind == CSG_AND ? (a & b) : (kind == CSG_OR ? (a | b) : (a & (b ^ 1u)));
            with = ((with >> 2u) << 1u) | c.x;
            without = ((without >> 2u) << 1u) | c.y;
        }
    }
    return ((with ^ without) & 1u) != 0u;
}

// From t on, where walked leaf k begins to matter again: t where the value just after t depends
// on it; else the next end of another leaf (INFINITY: never), the others' insides holding till
// then. Another walked leaf's opened interval may end anywhere before: then t.
float csg_moot_until(CsgNode node, vec2 inside[CSG_MAX_LEAVES], uint k, float t, uint walked) {
    if (csg_depends_on(node, inside, k, t)) return t;
    float until = INFINITY;
    for (uint j = 0u; j < node.leaf_count; ++j) {
        vec2 span = inside[j];
        if (j == k || !(span.x < span.y)) continue;
        if (span.y == INFINITY && ((walked >> j) & 1u) != 0u) return t;
        if (span.x > t) until = min(until, span.x);
        if (span.y > t) until = min(until, span.y);
    }
    return until;
}

bool csg_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    if (box_entry(p.p0.xyz, p.p1.xyz, ray.origin, safe_inverse(ray.dir), t_max) == INFINITY) return false;
    CsgNode node = csg_node_at(p.data);
    vec2 inside[CSG_MAX_LEAVES];
    vec4 ends_uv[CSG_MAX_LEAVES];  // a walked leaf's uv and error at its interval's ends (csg_walk)
    vec2 ends_error[CSG_MAX_LEAVES];
    uint walked = 0u;  // the walked leaves
    for (uint k = 0u; k < node.leaf_count; ++k) {
        Primitive leaf = primitive_at(node.first_leaf + k);
        if (csg_walked(leaf)) {
            walked |= 1u << k;
            inside[k] = vec2(INFINITY, -INFINITY);
            ends_uv[k] = vec4(0.0);
            ends_error[k] = vec2(0.0);
        } else {
            inside[k] = csg_inside(leaf, ray);
        }
    }
    uint walk = walked;  // those whose next interval is to be found, from inside[k].y on
    float t = t_min;
    // Each guarded by the constant CSG_MAY_WALK: without it, scenes without walked leaves lost 7%.
    for (uint step = 0u; step < (CSG_MAY_WALK ? CSG_MAX_ENDS : 2u * CSG_MAX_LEAVES); ++step) {
        if (CSG_MAY_WALK) {
            for (; walk != 0u; walk &= walk - 1u) {  // one call: lavapipe inlines each
                uint k = uint(findLSB(walk));
                Primitive leaf = primitive_at(node.first_leaf + k);
                // Where the value does not depend on the leaf from t on, its roots up to where it
                // matters again are not looked for (a difference's leaf within what it takes
                // away): its walk starts afresh there. (Last of the leaves walked at t: the others'
                // insides are then known.)
                float from = (walk & (walk - 1u)) == 0u && !csg_crossed(leaf) ? csg_moot_until(node, inside, k, t, walked) : t;
                if (from == INFINITY) inside[k] = vec2(INFINITY, -INFINITY);
                else inside[k] = csg_walk(p, leaf, ray, from > t ? vec2(INFINITY, -INFINITY) : inside[k], t, from, ends_uv[k], ends_error[k]);
            }
        }
        float next = t_max, end = 0.0;
        uint leaf = NO_PRIMITIVE;
        for (uint k = 0u; k < node.leaf_count; ++k) {
            vec2 span = inside[k];
            if (!(span.x < span.y)) continue;
            if (span.x > t && span.x < next) { next = span.x; leaf = k; end = 0.0; }
            if (span.y > t && span.y < next) { next = span.y; leaf = k; end = 1.0; }
        }
        if (CSG_MAY_WALK) {  // an opened interval begun before the next end may end before it: its end first
            for (uint w = walked; w != 0u; w &= w - 1u) {
                uint k = uint(findLSB(w));
                if (inside[k].y == INFINITY && inside[k].x < next) walk |= 1u << k;
            }
            if (walk != 0u) continue;
        }
        if (leaf == NO_PRIMITIVE) return false;
        if (csg_value(node, inside, next, false) != csg_value(node, inside, next, true)) {
            t_hit = next;
            bool at_root = CSG_MAY_WALK && ((walked >> leaf) & 1u) != 0u;
            uv = vec2(float(node.first_leaf + leaf), at_root ? 2.0 : end);
            if (at_root) {
                csg_walked_root = vec4(uv.x, next, end == 0.0 ? ends_uv[leaf].xy : ends_uv[leaf].zw);
                csg_walked_root_error = end == 0.0 ? ends_error[leaf].x : ends_error[leaf].y;
            }
            return true;
        }
        if (CSG_MAY_WALK && end == 1.0 && ((walked >> leaf) & 1u) != 0u) walk = 1u << leaf;  // past its interval: the next
        t = next;
    }
    return false;
}

// The leaf's own hit at a CSG hit at t (uv as csg_intersect left it): its primitive, its (u, v),
// and for a walked leaf, the error of its root found again there.
uint csg_leaf_hit(Primitive node, Ray ray, float t, vec2 csg_uv, out vec2 uv, inout float error) {
    uint leaf = uint(csg_uv.x);
    Primitive p = primitive_at(leaf);
    uv = vec2(0.0);
    bool walked = csg_uv.y == 2.0;
    if (csg_crossed(p)) {  // the piece that holds the crossing, itself shaded
        float t_leaf, leaf_error;
        uint piece;
        bool leaving;
        if (!csg_crossing(p, ray, t - csg_walk_gap(node, t), INFINITY, t_leaf, uv, leaf_error, piece, leaving))
            return p.type == SHAPE_MESH ? leaf : p.data;
        error = max(error, leaf_error + abs(t_leaf - t));
        return piece == NO_PRIMITIVE ? leaf : piece;
    }
    if (walked && csg_walked_root.xy == vec2(csg_uv.x, t)) {  // the root as the walk found it
        uv = csg_walked_root.zw;
        error = max(error, csg_walked_root_error);
    } else if (walked || p.type != SHAPE_PLANE) {
        float t_leaf, leaf_error;
        // A walked root is looked for again within the gap about it, where few of the leaf's
        // pieces reach.
        float gap = csg_walk_gap(node, t);
        float from = walked ? t - gap : -INFINITY, to = walked ? t + gap : INFINITY;
        bool found = leaf_hit(p, csg_uv.y == 1.0 ? Ray(ray.origin, -ray.dir) : ray, from, to, SHAPE_SOLID | SHAPE_CLOSED, t_leaf, uv, leaf_error);
        if (found && walked) error = max(error, leaf_error + abs(t_leaf - t));
    }
    return leaf;
}

// Never called: closest_hit shades a CSG hit as its leaf's.
vec3 csg_hit_normal(Primitive p, Ray ray, float t, vec3 point, vec2 uv, inout float error) { return vec3(0.0, 0.0, 1.0); }
vec2 csg_texture_uv(Primitive p, Hit hit, vec3 point) { return hit.uv; }

#endif

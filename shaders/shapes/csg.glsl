// CSG: POV-Ray's intersection, difference and merge (scene/scene.hpp's Csg). Twin of
// host/cpu/shapes/csg.cpp, written apart. p0, p1 = the combination's box (xyz), data = its
// CsgNode. Its leaves (SHAPE_SOLID: convex solids and half-spaces) are each inside along the ray
// on one interval: from their first hit from -infinity to the reversed ray's (a half-space's
// reaches to infinity). The combination's surface is the first end of an interval, beyond t_min, where the
// program's value changes: comparing ends, not counting crossings, stays exact where a ray
// grazes a leaf (an interval of no length changes nothing). A hit is the leaf's: uv = (the
// leaf's primitive, 0 at its interval's entry or 1 at its exit), which closest_hit resolves
// (csg_leaf_hit) so that the leaf's normal, material and texture shade it.
#ifndef LANCER_CSG_GLSL
#define LANCER_CSG_GLSL

// The leaf's inside along the ray: (in, out), empty where in >= out.
vec2 csg_inside(Primitive leaf, Ray ray) {
    float t_in, t_out;
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
    // could find the entry again or step past a close exit.
    if (!leaf_hit(leaf, ray, -INFINITY, INFINITY, t_in, uv)) return vec2(INFINITY, -INFINITY);
    if (!leaf_hit(leaf, Ray(ray.origin, -ray.dir), -INFINITY, INFINITY, t_out, uv)) return vec2(INFINITY, -INFINITY);
    return vec2(t_in, -t_out);  // in >= out: a touching ray, no length
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

bool csg_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    if (box_entry(p.p0.xyz, p.p1.xyz, ray.origin, safe_inverse(ray.dir), t_max) == INFINITY) return false;
    CsgNode node = csg_node_at(p.data);
    vec2 inside[CSG_MAX_LEAVES];
    for (uint k = 0u; k < node.leaf_count; ++k) inside[k] = csg_inside(primitive_at(node.first_leaf + k), ray);
    float t = t_min;
    for (uint step = 0u; step < 2u * CSG_MAX_LEAVES; ++step) {
        float next = t_max, end = 0.0;
        uint leaf = NO_PRIMITIVE;
        for (uint k = 0u; k < node.leaf_count; ++k) {
            vec2 span = inside[k];
            if (!(span.x < span.y)) continue;
            if (span.x > t && span.x < next) { next = span.x; leaf = k; end = 0.0; }
            if (span.y > t && span.y < next) { next = span.y; leaf = k; end = 1.0; }
        }
        if (leaf == NO_PRIMITIVE) return false;
        if (csg_value(node, inside, next, false) != csg_value(node, inside, next, true)) {
            t_hit = next;
            uv = vec2(float(node.first_leaf + leaf), end);
            return true;
        }
        t = next;
    }
    return false;
}

// The leaf's own hit at a CSG hit (uv as csg_intersect left it): its primitive, and its (u, v).
uint csg_leaf_hit(Ray ray, vec2 csg_uv, out vec2 uv) {
    uint leaf = uint(csg_uv.x);
    Primitive p = primitive_at(leaf);
    float t;
    uv = vec2(0.0);
    if (p.type != SHAPE_PLANE) leaf_hit(p, csg_uv.y != 0.0 ? Ray(ray.origin, -ray.dir) : ray, -INFINITY, INFINITY, t, uv);
    return leaf;
}

// Never called: closest_hit shades a CSG hit as its leaf's.
vec3 csg_hit_normal(Primitive p, Ray ray, float t, vec3 point, vec2 uv, inout float error) { return vec3(0.0, 0.0, 1.0); }
vec2 csg_texture_uv(Primitive p, Hit hit, vec3 point) { return hit.uv; }

#endif

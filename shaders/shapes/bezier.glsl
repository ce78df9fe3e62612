// Ray/bicubic (rational) Bezier patch by Bezier clipping (Nishita, Sederberg & Kakimoto 1990).
// Twin of host/cpu/shapes/bezier.cpp, which solves the same problem exactly by resultants and
// LAPACK; the two share nothing but the patch data.
//
// The ray is the intersection of two planes through it. In the 2-D coordinates those planes
// give, the ray is the origin, and a point of the patch is on the ray iff its projection is
// (0, 0). The projected patch is again a Bezier patch, so by the convex hull property each
// clip step can cut away the parts of the parameter box whose control points cannot reach
// the origin. Boxes that stop shrinking are split; a box narrower than BEZIER_EPS in both
// directions is a hit.

// The small fixed loops are [[unroll]]ed: lavapipe counts every iteration of a loop that stays a
// loop against its per-invocation limit (see loop_limit_reached in trace.comp), and unrolled they also run faster.
const float BEZIER_EPS = 1e-5;     // converged box width, in the leaf's own parameters
const float BEZIER_SLACK = 1e-6;   // absolute widening of each clip, in the leaf's parameters
const int BEZIER_STACK = 32;       // pending boxes after splits
const int BEZIER_MAX_STEPS = 400;  // clip steps per ray and leaf (measured: 4-10 typical, 38 worst in 20,000)

// A homogeneous point's distance along the ray. Without rational patches in the scene every
// weight is 1, and the net's w, with its divisions, is left out (the teapot 5-9% faster; the
// packer normalises a leaf's weights, so a polynomial patch has exactly 1).
float ray_distance(vec4 h) { return SCENE_HAS_RATIONAL_PATCHES ? h.z / h.w : h.z; }

// The part [a, b] of the cubic with coefficients c0..c3, by two de Casteljau splits.
void cubic_restrict(inout vec4 c0, inout vec4 c1, inout vec4 c2, inout vec4 c3, float a, float b) {
    // Keep [0, b].
    vec4 p01 = mix(c0, c1, b), p12 = mix(c1, c2, b), p23 = mix(c2, c3, b);
    vec4 p012 = mix(p01, p12, b), p123 = mix(p12, p23, b);
    c1 = p01;
    c2 = p012;
    c3 = mix(p012, p123, b);
    // Of that, keep [a / b, 1].
    float s = b > 0.0 ? a / b : 0.0;
    p01 = mix(c0, c1, s);
    p12 = mix(c1, c2, s);
    p23 = mix(c2, c3, s);
    p012 = mix(p01, p12, s);
    p123 = mix(p12, p23, s);
    c0 = mix(p012, p123, s);
    c1 = p123;
    c2 = p23;
}

// net[4i + j] restricted to the box (u0, u1, v0, v1).
void net_restrict(inout vec4 net[16], vec4 box) {
    [[unroll]] for (int i = 0; i < 4; ++i) cubic_restrict(net[4 * i], net[4 * i + 1], net[4 * i + 2], net[4 * i + 3], box.z, box.w);
    [[unroll]] for (int j = 0; j < 4; ++j) cubic_restrict(net[j], net[4 + j], net[8 + j], net[12 + j], box.x, box.y);
}

// Widens `range` to the point where the segment (xa, ea)-(xb, eb) crosses e = 0, if it does.
void add_crossing(float xa, float ea, float xb, float eb, inout vec2 range) {
    if (ea == 0.0) range = vec2(min(range.x, xa), max(range.y, xa));
    if ((ea < 0.0) == (eb < 0.0)) return;
    float x = xa + (xb - xa) * (ea / (ea - eb));
    range = vec2(min(range.x, x), max(range.y, x));
}

// Where the convex hull of the points (k/3, lo[k]) and (k/3, hi[k]) meets the axis e = 0, as
// an interval of [0, 1] (empty when x > y). Since lo[k] <= hi[k] at each x, the hull's boundary
// is the lower hull of the lo points, the upper hull of the hi points and the verticals at
// x = 0 and 1: the hull meets the axis in the span of the crossings of lo-lo and hi-hi segments
// and of those two verticals (segments inside the hull cross within that span, so the lo-hi
// pairs and the inner verticals are left out: the teapot 7% faster, the same picture).
// Written without a loop over pairs: a loop whose inner bound varies is not unrolled, and
// every iteration counts against lavapipe's per-invocation loop limit (see loop_limit_reached
// in trace.comp).
vec2 hull_axis_interval(vec4 lo, vec4 hi) {
    vec2 range = vec2(1.0, 0.0);
    // The verticals at x = 0 and 1 (add_crossing also takes lo == 0; hi == 0 is taken here).
    add_crossing(0.0, lo[0], 0.0, hi[0], range);
    add_crossing(1.0, lo[3], 1.0, hi[3], range);
    if (hi[0] == 0.0) range = vec2(min(range.x, 0.0), max(range.y, 0.0));
    if (hi[3] == 0.0) range = vec2(min(range.x, 1.0), max(range.y, 1.0));
    // The lower and the upper hull's edges, among the lo-lo and hi-hi segments.
    [[unroll]] for (int i = 0; i < 4; ++i) {
        float xi = float(i) / 3.0;
        [[unroll]] for (int j = 0; j < 4; ++j) {
            if (j <= i) continue;
            float xj = float(j) / 3.0;
            add_crossing(xi, lo[i], xj, lo[j], range);
            add_crossing(xi, hi[i], xj, hi[j], range);
        }
    }
    return range;
}

// The sub-interval of [0, 1] in u (along_u) or v that can contain a root, from the signed
// distances of the projected control points to the line through the origin along `line`.
vec2 clip_interval(vec4 net[16], vec2 line, bool along_u, float eps) {
    float len = length(line);
    vec2 n = len > 1e-30 ? vec2(-line.y, line.x) / len : vec2(1.0, 0.0);  // collapsed edge: any line is valid
    vec4 lo = vec4(INFINITY), hi = vec4(-INFINITY);
    [[unroll]] for (int i = 0; i < 4; ++i) {
        [[unroll]] for (int j = 0; j < 4; ++j) {
            float e = dot(n, net[4 * i + j].xy);
            int k = along_u ? i : j;
            lo[k] = min(lo[k], e);
            hi[k] = max(hi[k], e);
        }
    }
    // Widened by the rounding error of the distances: a root exactly on the patch's edge (where
    // neighbouring patches meet) must not fall out through a crack of float noise.
    return hull_axis_interval(lo - vec4(eps), hi + vec4(eps));
}

// The hit's error: the true root lies on the ray within the converged piece's hull, whose extent
// along the ray is [tlo, thi], so the hit at the corners' mean t is within thi - tlo of it, to
// the rounding of the hull's t values: the projection of the net (5 roundings of extent, the
// largest w |q|) and the de Casteljau steps of the restriction (2 splits of 3 levels in each
// direction, up to 3 roundings a level: 36), 48 with the division by w. The clipping accepts any
// piece within eps (in homogeneous units: eps / w in space) of the ray, so that again keeps the
// intersector from finding the piece it leaves from a new origin. Plus the rounding of the
// re-origined ray and of the hit point.
// With any_root, the first root found in (t_min, t_max) ends the search: a shadow ray is blocked
// by any, and need not find the nearest.
bool bezier_search(Primitive prim, Ray ray, float t_min, float t_max, bool any_root, out float t_hit, out vec2 uv_hit, out float error) {
    uint leaf = prim.data;
    vec3 o = ray.origin - patch_leaf_at(leaf).origin.xyz;  // re-origin: small numbers near the patch
    vec3 d = ray.dir;
    // Two planes through the ray: n1, n2 perpendicular to d and to each other.
    vec3 a = abs(d.x) <= abs(d.y) && abs(d.x) <= abs(d.z) ? vec3(1.0, 0.0, 0.0)
           : (abs(d.y) <= abs(d.z) ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
    vec3 n1 = normalize(cross(d, a));
    vec3 n2 = cross(d, n1);
    // Homogeneous net: (w * plane distances, w * ray distance, w). De Casteljau on homogeneous
    // points is exact for rational patches, and since w > 0 the numerators' signs decide.
    vec4 base[16];
    float extent = 0.0;
    [[unroll]] for (int k = 0; k < 16; ++k) {
        vec4 p = patch_leaf_at(leaf).points[k];
        float w = SCENE_HAS_RATIONAL_PATCHES ? p.w : 1.0;
        vec3 q = p.xyz - o;
        base[k] = w * vec4(dot(n1, q), dot(n2, q), dot(d, q), 1.0);
        extent = max(extent, w * length(q));
    }
    // How far float rounding can move a projected control point off its true place.
    float eps = 4e-7 * extent;

    vec4 stack[BEZIER_STACK];
    int sp = 0;
    vec4 box = vec4(0.0, 1.0, 0.0, 1.0);
    float best = t_max;
    float best_error = 0.0;
    bool found = false;
    for (int step = 0; step < BEZIER_MAX_STEPS; ++step) {
        vec4 net[16] = base;
        net_restrict(net, box);
        vec2 dlo = vec2(INFINITY), dhi = vec2(-INFINITY);
        float tlo = INFINITY, thi = -INFINITY, wlo = INFINITY;
        [[unroll]] for (int k = 0; k < 16; ++k) {
            dlo = min(dlo, net[k].xy);
            dhi = max(dhi, net[k].xy);
            wlo = SCENE_HAS_RATIONAL_PATCHES ? min(wlo, net[k].w) : 1.0;
            float t = ray_distance(net[k]);
            tlo = min(tlo, t);
            thi = max(thi, t);
        }
        bool done = any(greaterThan(dlo, vec2(eps))) || any(lessThan(dhi, vec2(-eps))) || tlo >= best || thi <= t_min;
        // Converged: the box is tiny in parameters, or the piece of surface it covers is tiny in
        // space (where the parametrisation degenerates, as at the teapot's lid apex, a whole
        // edge of roots maps to one point and the parameter box never shrinks along it).
        bool tiny_box = box.y - box.x < BEZIER_EPS && box.w - box.z < BEZIER_EPS;
        bool tiny_piece = max(dhi.x - dlo.x, dhi.y - dlo.y) < 4.0 * eps && thi - tlo < 4.0 * eps;
        if (!done && (tiny_box || tiny_piece)) {
            // Converged: the corners of the restricted net lie on the surface.
            float t = 0.25 * (ray_distance(net[0]) + ray_distance(net[3]) + ray_distance(net[12]) + ray_distance(net[15]));
            if (t > t_min && t < best) {
                best = t;
                best_error = (thi - tlo) + (eps + rounding_bound(48.0, extent)) / wlo;
                uv_hit = vec2(0.5 * (box.x + box.y), 0.5 * (box.z + box.w));
                found = true;
                if (any_root) sp = 0;
            }
            done = true;
        }
        if (!done) {
            // u-clip against the line along the v-direction, v-clip against the u-direction.
            vec2 v_dir = (net[3].xy - net[0].xy) + (net[15].xy - net[12].xy);
            vec2 u_dir = (net[12].xy - net[0].xy) + (net[15].xy - net[3].xy);
            vec2 cu = clip_interval(net, v_dir, true, eps);
            vec2 cv = clip_interval(net, u_dir, false, eps);
            if (cu.x > cu.y || cv.x > cv.y) {
                done = true;
            } else {
                // Slack, so float rounding cannot cut off a root at the hull's edge: relative, and an
                // absolute 1e-6 in the leaf's parameters, where the restricted net's rounding noise
                // is as large as the box itself (without it, 29% of teapot rays lost their root).
                vec2 w = vec2(box.y - box.x, box.w - box.z);
                vec2 slack = vec2(1e-4) + BEZIER_SLACK / w;
                cu = clamp(cu + vec2(-slack.x, slack.x), 0.0, 1.0);
                cv = clamp(cv + vec2(-slack.y, slack.y), 0.0, 1.0);
                vec4 clipped = vec4(box.x + w.x * cu.x, box.x + w.x * cu.y, box.z + w.y * cv.x, box.z + w.y * cv.y);
                vec2 nw = vec2(clipped.y - clipped.x, clipped.w - clipped.z);
                if (nw.x > 0.8 * w.x && nw.y > 0.8 * w.y) {
                    // Clipping stalled (several roots, or a tangent): split the wider side, and go on
                    // with the half whose corners (points of the surface) are nearer, the other
                    // waiting. Nearer first, a root found early prunes what lies behind it; the
                    // other way round, a tangent behind the nearest root can take every step left
                    // (BEZIER_MAX_STEPS) in a cloud of tiny boxes before the root's half is seen.
                    // (Written as a choice of the half to push and of the side to cut, not of two
                    // boxes: the teapot took 1.2 times as long with that.)
                    if (sp < BEZIER_STACK) {
                        float t00 = ray_distance(net[0]), t01 = ray_distance(net[3]);
                        float t10 = ray_distance(net[12]), t11 = ray_distance(net[15]);
                        if (nw.x >= nw.y) {
                            float m = 0.5 * (clipped.x + clipped.y);
                            bool low_first = min(t00, t01) <= min(t10, t11);
                            stack[sp++] = low_first ? vec4(m, clipped.y, clipped.z, clipped.w) : vec4(clipped.x, m, clipped.z, clipped.w);
                            if (low_first) clipped.y = m; else clipped.x = m;
                        } else {
                            float m = 0.5 * (clipped.z + clipped.w);
                            bool low_first = min(t00, t10) <= min(t01, t11);
                            stack[sp++] = low_first ? vec4(clipped.x, clipped.y, m, clipped.w) : vec4(clipped.x, clipped.y, clipped.z, m);
                            if (low_first) clipped.w = m; else clipped.z = m;
                        }
                    }
                }
                box = clipped;
            }
        }
        if (done) {
            if (sp == 0) break;
            box = stack[--sp];
        }
    }
    if (!found) return false;
    t_hit = best;
    error = best_error + rounding_bound(16.0, max_abs(ray.origin) + max_abs(patch_leaf_at(leaf).origin.xyz) + best);
    return true;
}

// A leaf's nearest root, or for a shadow ray (element_tree.glsl's shadow_ray_any_hit) any root.
bool bezier_intersect(Primitive prim, Ray ray, float t_min, float t_max, out float t_hit, out vec2 uv_hit, out float error) {
    return bezier_search(prim, ray, t_min, t_max, shadow_ray_any_hit, t_hit, uv_hit, error);
}

// S, dS/du, dS/dv of the leaf at its own (u, v), relative to its origin (rational-correct).
void bezier_leaf_eval(uint leaf, vec2 uv, out vec3 P, out vec3 Pu, out vec3 Pv) {
    float u = uv.x, v = uv.y, iu = 1.0 - u, iv = 1.0 - v;
    vec4 bu = vec4(iu * iu * iu, 3.0 * u * iu * iu, 3.0 * u * u * iu, u * u * u);
    vec4 bv = vec4(iv * iv * iv, 3.0 * v * iv * iv, 3.0 * v * v * iv, v * v * v);
    vec4 du = 3.0 * vec4(-iu * iu, iu * iu - 2.0 * u * iu, 2.0 * u * iu - u * u, u * u);
    vec4 dv = 3.0 * vec4(-iv * iv, iv * iv - 2.0 * v * iv, 2.0 * v * iv - v * v, v * v);
    vec4 h = vec4(0.0), hu = vec4(0.0), hv = vec4(0.0);
    [[unroll]] for (int i = 0; i < 4; ++i) {
        [[unroll]] for (int j = 0; j < 4; ++j) {
            vec4 p = patch_leaf_at(leaf).points[4 * i + j];
            vec4 hp = vec4(p.xyz * p.w, p.w);
            h += bu[i] * bv[j] * hp;
            hu += du[i] * bv[j] * hp;
            hv += bu[i] * dv[j] * hp;
        }
    }
    P = h.xyz / h.w;
    Pu = (hu.xyz - P * hu.w) / h.w;
    Pv = (hv.xyz - P * hv.w) / h.w;
}

// The unit normal at a hit. Where the patch degenerates (an edge collapsed to a point, as at
// the teapot's lid apex) Su x Sv vanishes; the limit normal is taken slightly inside the leaf.
vec3 bezier_hit_normal(Primitive prim, Ray ray, float t, vec3 p, vec2 uv, inout float error) {
    vec3 P, Pu, Pv;
    bezier_leaf_eval(prim.data, uv, P, Pu, Pv);
    // The partials scaled together by a power of two first (unit_scale): a patch 1e10 across
    // would otherwise square them past float's range.
    float s = unit_scale(max(max_abs(Pu), max_abs(Pv)));
    vec3 u = s * Pu, v = s * Pv;
    vec3 n = cross(u, v);
    float scale = dot(u, u) + dot(v, v);
    if (dot(n, n) <= 1e-12 * scale * scale) {
        bezier_leaf_eval(prim.data, mix(uv, vec2(0.5), 1e-3), P, Pu, Pv);
        s = unit_scale(max(max_abs(Pu), max_abs(Pv)));
        n = cross(s * Pu, s * Pv);
    }
    float len = length(n);
    return len > 0.0 ? n / len : vec3(0.0, 0.0, 1.0);
}

// Texture (u, v): the hit's parameters on its whole patch (a leaf's own are mapped to it).
vec2 bezier_texture_uv(Primitive prim, Hit hit, vec3 p) {
    vec4 dom = patch_leaf_at(prim.data).domain;
    return vec2(mix(dom.x, dom.y, hit.uv.x), mix(dom.z, dom.w, hit.uv.y));
}

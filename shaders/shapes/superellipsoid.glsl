// Ray/superellipsoid (POV-Ray's superellipsoid { <e, n> }), exactly, in float, in its own
// coordinates (it is always placed: placement.glsl carries rays there, with unit directions).
// Twin of host/cpu/shapes/superellipsoid.cpp (the same idea in double, with a bracket refined
// to double precision). p.p0 = (p, q, 1 / p, 1 / q) with p = 2 / e and q = 2 / n, both >= 1.
//
// The solid is g = (|x|^p + |y|^p)^(q/p) + |z|^q <= 1. F = g^(1/q), the q-norm of (the p-norm of
// (x, y), |z|), is a norm: F along a ray is convex, F >= max(|x|, |y|, |z|) (so F > 1 on the
// faces of the box [-B, B]^3, B > 1), and its gradient on the surface is between 1 / sqrt(3) and
// sqrt(3) long: F's rounding is a distance of the same order, however large the exponents.
// Norms of pairs are evaluated from their larger member m as m (1 + (small / m)^p)^(1/p) with
// exp2 and log2: no overflow for p up to 2000, and (small / m)^p's relative error, p times that
// of the log, is divided by p again in the p-th root.
//
// The ray is carried to its point c nearest the centre (as the torus's), clipped to the box and
// (t_min, t_max). Where F > 1 at the stretch's start, Newton's method on F = 1 from there climbs
// toward the first root without passing it (a convex F lies above its tangents); where the
// tangent's slope is no longer negative while F > 1, the ray misses (F stays above 1 beyond),
// and where an iterate passes the stretch's end, the root is not in it. Where F <= 1 at the
// start (a ray from inside, CSG's reversed rays), the hit is the exit: the same from the end,
// backward. Measured in float (this code in C++, 200,000 rays aimed into the box per shape, e and
// n from 0.001 to 2 and mixed): 1.0 to 2.9 steps on average, at most 11. Lines tangent to the
// surface near its edges and corners (20,000 per shape and offset): moved 1e-6 to 1e-2 off it,
// every one outside misses and every one inside hits, in at most 14 steps; exactly tangent
// (converging linearly, halving, toward the point of contact), at most 16.
const int SUPERELLIPSOID_STEPS = 24;
const float SUPERELLIPSOID_BOX = 1.0001;        // the box the ray is clipped to: F > 1 on its faces
const float SUPERELLIPSOID_TOLERANCE = 2.4e-7;  // a Newton step this short ends the search (4 roundings of 1)

// The norm with exponent k (ik = 1 / k) of (a, b), both >= 0: (value, d/da, d/db).
vec3 superellipsoid_pair(float a, float b, float k, float ik) {
    float big = max(a, b), small = min(a, b);
    if (big == 0.0) return vec3(0.0);
    float ratio = small / big;
    float power = ratio > 0.0 ? exp2(k * log2(ratio)) : 0.0;  // (small / big)^k
    float sum = 1.0 + power;
    float root = exp2(ik * log2(sum));  // sum^(1/k)
    float value = big * root;
    // d/d(big) = (big / value)^(k - 1) = root / sum; d/d(small) = ratio^(k - 1) times that (at
    // ratio 0, where k = 1: |small|'s slope 1, which the sign of the coordinate then takes).
    float d_big = root / sum;
    float d_small = ratio > 0.0 ? (power / ratio) * d_big : (k == 1.0 ? d_big : 0.0);
    return a >= b ? vec3(value, d_big, d_small) : vec3(value, d_small, d_big);
}

// F at x and its gradient (a subgradient at the kinks of |x| where p or q is 1: the sign of 0 is 0).
vec4 superellipsoid_level(vec4 k, vec3 x) {
    vec3 a = abs(x);
    vec3 across = superellipsoid_pair(a.x, a.y, k.x, k.z);
    vec3 whole = superellipsoid_pair(across.x, a.z, k.y, k.w);
    return vec4(whole.x, sign(x) * vec3(whole.y * across.y, whole.y * across.z, whole.z));
}

// From a, where F = f0 > 1 with gradient g0, along the unit direction d: the first s in
// (0, span] where F = 1 (Newton's last iterate, within SUPERELLIPSOID_TOLERANCE of it or where F
// reads 1 to rounding), or -1 where the ray does not come inside there.
float superellipsoid_march(vec4 k, vec3 a, vec3 d, float span, vec4 at) {
    float s = 0.0;
    for (int i = 0; i < SUPERELLIPSOID_STEPS; ++i) {
        float slope = dot(at.yzw, d);
        if (!(slope < 0.0)) return -1.0;
        float step = (at.x - 1.0) / -slope;
        s += step;
        if (!(s <= span)) return -1.0;
        if (step <= SUPERELLIPSOID_TOLERANCE) return s;
        at = superellipsoid_level(k, a + s * d);
        if (at.x <= 1.0) return s;
    }
    return -1.0;
}

bool superellipsoid_intersect(Primitive p, Ray ray, float t_min, float t_max, out float t_hit, inout vec2 uv, inout float error) {
    vec4 k = p.p0;
    // About c, the ray's point nearest the centre: u = t - tc.
    float tc = -dot(ray.origin, ray.dir);
    vec3 c = ray.origin + tc * ray.dir;
    vec3 inv = safe_inverse(ray.dir);
    vec3 ta = (vec3(-SUPERELLIPSOID_BOX) - c) * inv, tb = (vec3(SUPERELLIPSOID_BOX) - c) * inv;
    vec3 tn = min(ta, tb), tf = max(ta, tb);
    float lo = max(max(tn.x, tn.y), max(tn.z, t_min - tc));
    float hi = min(min(tf.x, tf.y), min(tf.z, t_max - tc));
    if (!(lo < hi)) return false;
    vec3 start = c + lo * ray.dir;
    vec4 at = superellipsoid_level(k, start);
    if (at.x > 1.0) {
        // Outside at the start: the first root, if any, is the hit (the exit is beyond it).
        float s = superellipsoid_march(k, start, ray.dir, hi - lo, at);
        if (s < 0.0) return false;
        float t = tc + (lo + s);
        if (t > t_min && t < t_max) {
            t_hit = t;
            return true;
        }
        // The entry is at t_min to rounding: the exit is the next surface.
    }
    // Inside at the start: the exit, searched backward from the stretch's end where that is outside.
    vec3 end = c + hi * ray.dir;
    at = superellipsoid_level(k, end);
    if (!(at.x > 1.0)) return false;
    float s = superellipsoid_march(k, end, -ray.dir, hi - lo, at);
    if (s < 0.0) return false;
    float t = tc + (hi - s);
    t_hit = t;
    return t > t_min && t < t_max;
}

// The hit's error (Hit.error), in its own coordinates:
//   c = o + tc d: 2 roundings of |o| + |tc| <= 2 max |o| (tc renames the point, its own rounding
//   moves nothing off the line); the stretch's start and the iterates c + u d: 2 roundings of
//   the box's scale each;
//   the root: Newton stops within SUPERELLIPSOID_TOLERANCE (4 roundings of 1) before it, or where
//   float's F reads 1: F's own rounding (the pairs' logs and powers, about 16 roundings of F's
//   scale, 1) over |grad F| >= 1 / sqrt(3): 28 roundings of 1;
//   t = tc + (lo + s): 2 roundings of |tc| + |u|; and the hit point's (hit_point_rounding).
// About 40 roundings of max |o| + t + 1; with a factor 1.6 of margin: 64.
float superellipsoid_hit_error(Ray ray, float t) { return rounding_bound(64.0, max_abs(ray.origin) + abs(t) + 1.0); }

// The outward normal: F's gradient, which does not vanish on the surface (there the sum of its
// components' magnitudes is at least 1, as F <= |x| + |y| + |z|).
vec3 superellipsoid_hit_normal(Primitive p, Ray ray, float t, vec3 point, vec2 uv, inout float error) {
    error = superellipsoid_hit_error(ray, t);
    vec3 g = superellipsoid_level(p.p0, point).yzw;
    float len = length(g);
    return len > 0.0 ? g / len : -ray.dir;
}

// Texture (u, v): x and y across [-1.01, 1.01] (the box it was drawn in as an implicit surface).
vec2 superellipsoid_texture_uv(Primitive p, Hit hit, vec3 point) { return (point.xy + 1.01) / 2.02; }

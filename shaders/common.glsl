// Rays, hits, their error bounds and the rule for where secondary rays start.
#ifndef LANCER_COMMON_GLSL
#define LANCER_COMMON_GLSL

const float INFINITY = 1.0 / 0.0;

struct Ray {
    vec3 origin;
    vec3 dir;  // unit length
};

struct Hit {
    float t;
    vec3 normal;  // unit, not yet flipped toward the ray
    vec2 uv;      // the surface's own parameters, where it has them
    uint primitive;
    float error;  // how far ray.origin + t * ray.dir, computed in float, can be from the surface
};

// Float's unit roundoff, 2^-24: one rounding moves a value x by at most |x| times this.
const float FLOAT_ROUNDING = 5.9604645e-8;

float max_abs(vec3 v) { return max(abs(v.x), max(abs(v.y), abs(v.z))); }

// The power of two 2^-e that brings `magnitude` into [0.5, 1) (1 for 0, inf or NaN). Vectors
// scaled by it before they are squared (lengths, cross products, gradients) neither overflow nor
// underflow within lancer's 1e12 range, and as the scaling is exact, a quotient of terms of the
// same degree (a unit vector, a parameter) comes out bit for bit as without it.
float unit_scale(float magnitude) {
    if (!(magnitude > 0.0) || isinf(magnitude)) return 1.0;
    int e;
    frexp(magnitude, e);
    return ldexp(1.0, -e);
}

// What k roundings of numbers no larger than `magnitude` can add up to (pbrt's gamma(k) times
// the magnitude, for the small k used here). Each intersector bounds its hit's error with it,
// the magnitudes being those of the ray's origin, the hit's t and the shape's data: positions
// are relative to the GPU's anchor near the camera (gpu/packing/float_anchor), so they grow with the
// distance from the camera, as does the rounding of every point computed from them.
float rounding_bound(float k, float magnitude) { return k * FLOAT_ROUNDING * magnitude; }

// The rounding of the hit point p = origin + t * dir as the callers compute it (a product and a
// sum per coordinate: 2 roundings of numbers up to |origin| + t, along any unit normal sqrt(3)
// times that), and of t itself (relative).
float hit_point_rounding(vec3 origin, float t) { return rounding_bound(4.0, max_abs(origin) + 2.0 * t); }

// How far off the surface a secondary ray starts (pbrt's OffsetRayOrigin): twice the hit's error
// bound, once for the hit point's own error and once for the intersector's, which looks at the
// surface again from the new origin with errors of the same size; plus the rounding of the new
// origin itself (one rounding per coordinate of numbers up to |p|, along n at most 2 of them).
// So a ray leaving the surface never meets it again at t ~ 0 (no acne), and starts no further
// from it than its rounding requires (contact shadows, thin features).
float spawn_offset(vec3 p, float error) { return 2.0 * error + rounding_bound(4.0, max_abs(p)); }

// The origin of a ray leaving the surface at p to the side of the unit normal n (shadow rays,
// reflections).
vec3 offset_origin(vec3 p, vec3 n, float error) { return p + spawn_offset(p, error) * n; }

// The origin of a ray going on through the surface at p along d (refraction, transparent
// surfaces passed through): the offset past the surface's tangent plane, on the ray's own line,
// so that a path through a medium keeps its true length (Beer-Lambert). A grazing ray (|d.n| below
// 0.1, 6 degrees) would go far along its line for that and, where the surface curves, could leave
// it on the other side of a thin sliver: it goes at most 10 offsets along, the rest straight
// across.
vec3 past_surface(vec3 p, vec3 n, vec3 d, float error) {
    float offset = spawn_offset(p, error);
    float c = abs(dot(d, n));
    float along = offset / max(c, 0.1);
    vec3 across = dot(d, n) < 0.0 ? -n : n;  // the unit normal on the side d goes to
    return p + along * d + max(0.0, offset - along * c) * across;
}

// Distance at which the ray enters the box, or INFINITY if it misses it within [0, t_max].
float box_entry(vec3 lo, vec3 hi, vec3 origin, vec3 inv_dir, float t_max) {
    vec3 t0 = (lo - origin) * inv_dir;
    vec3 t1 = (hi - origin) * inv_dir;
    vec3 tn = min(t0, t1);
    vec3 tf = max(t0, t1);
    float enter = max(max(tn.x, tn.y), max(tn.z, 0.0));
    float leave = min(min(tf.x, tf.y), min(tf.z, t_max));
    return enter <= leave ? enter : INFINITY;
}

// 1/d with zero components replaced by a huge finite value of the same sign: keeps the slab
// test free of 0 * inf = NaN for axis-parallel rays.
vec3 safe_inverse(vec3 d) {
    const float tiny = 1e-30;
    vec3 s = vec3(d.x < 0.0 ? -1.0 : 1.0, d.y < 0.0 ? -1.0 : 1.0, d.z < 0.0 ? -1.0 : 1.0);
    return s / max(abs(d), vec3(tiny));
}

#endif

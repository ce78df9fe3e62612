// Rays, hits and the robust-offset rule shared by every shape file.
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
};

// Secondary rays start this far from the surface, scaled by the hit point's magnitude so that
// float rounding of the hit position (which grows with |p|) can never put the new origin back
// behind the surface: no shadow acne, no dark dots on planes.
float ray_offset(vec3 p) {
    return 1e-4 * max(1.0, max(abs(p.x), max(abs(p.y), abs(p.z))));
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

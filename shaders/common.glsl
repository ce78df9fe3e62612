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

#endif

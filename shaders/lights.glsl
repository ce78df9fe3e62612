// Lights: the points a shading point sees each light from (the light itself, or the n x n
// samples of an area light) and how much of its colour arrives there (spot cone, distance
// fall-off). Twin of host/cpu/lights.cpp; docs/scene-format.md states the formulas.
#ifndef LANCER_LIGHTS_GLSL
#define LANCER_LIGHTS_GLSL

// PCG's 32-bit output permutation: exact integer arithmetic, so the CPU reference computes the
// same bits and both backends put area light samples at the same places.
uint hash_u32(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// The top 24 bits of a hash as a number in [0, 1): exact in float and in double.
float unit_interval(uint h) { return float(h >> 8u) * (1.0 / 16777216.0); }

// Number of point samples of a light: n x n for an area light, else 1.
uint light_sample_count(Light light) {
    return SCENE_HAS_AREA_LIGHTS && light.type == LIGHT_AREA ? light.samples * light.samples : 1u;
}

// Sample s of light number `index`: the light's position, or for an area light a point in cell
// (s mod n, s / n) of its rectangle, at the cell's centre or, jittered, at a place hashed from
// `seed` (camera sample and shading point), the light and the sample.
vec3 light_sample_position(Light light, uint index, uint s, uint seed) {
    if (!SCENE_HAS_AREA_LIGHTS || light.type != LIGHT_AREA) return light.position.xyz;
    uint n = light.samples;
    vec2 offset = vec2(0.5);
    if (light.jitter != 0u) {
        uint h = hash_u32(seed ^ hash_u32((index << 8u) | s));
        offset = vec2(unit_interval(h), unit_interval(hash_u32(h)));
    }
    vec2 ab = (vec2(float(s % n), float(s / n)) + offset) / float(n) - 0.5;
    return light.position.xyz + ab.x * light.edge_u.xyz + ab.y * light.edge_v.xyz;
}

// POV-Ray's spotlight: cos^tightness of the angle to the axis, times a cubic that rises from 0
// at outer_angle to 1 at inner_angle; 0 behind the light.
float spot_factor(Light light, vec3 from_light) {
    float c = dot(from_light, light.direction.xyz);
    float lo = light.spot.x, hi = light.spot.y;  // cos(outer_angle) <= cos(inner_angle)
    if (c <= 0.0 || c < lo) return 0.0;
    float f = light.spot.z > 0.0 ? pow(c, light.spot.z) : 1.0;
    if (c >= hi) return f;
    float t = (c - lo) / (hi - lo);
    return f * (3.0 - 2.0 * t) * t * t;
}

// The light's colour arriving at p from its sample q, one of `count` samples.
vec3 light_intensity(Light light, vec3 q, vec3 p, uint count) {
    vec3 c = light.color.rgb;
    if (SCENE_HAS_AREA_LIGHTS && count > 1u) c /= float(count);
    if (SCENE_HAS_SPOT_LIGHTS && light.type == LIGHT_SPOT) c *= spot_factor(light, normalize(p - q));
    if (SCENE_HAS_FALLOFF && light.position.w > 0.0) {
        float r = light.position.w / length(p - q);  // 1 at the fall-off distance
        c *= light.direction.w > 0.0 ? 2.0 / (1.0 + pow(r, -light.direction.w)) : r * r;  // POV-Ray's fade, or 1/d^2
    }
    return c;
}

#endif

// What a material looks like at a hit: its pigment (colour or checker, times texture, times
// pattern) and its shading normal (tilted by a bump). Twin of host/cpu/appearance.cpp.
#ifndef LANCER_APPEARANCE_GLSL
#define LANCER_APPEARANCE_GLSL

#include "pattern.glsl"
#include "texture.glsl"

struct Appearance {
    vec3 pigment;
    vec3 normal;  // unit, the geometric normal unless a bump tilts it
};

// n: the unit geometric normal, already facing the viewer.
Appearance appearance_at(Material m, Hit hit, vec3 p, vec3 n) {
    // Checkers and patterns are fixed to their object: evaluated at its own coordinates.
    vec3 q = p;
    ObjectFrame frame;
    bool world = true;  // the object's coordinates are the world's
    if (PLACED_OBJECTS) {
        frame = object_frame_at(primitive_at(hit.primitive).object);
        q = object_point(frame, p);
        world = frame.world != 0u;
    }
    // A checker without a transform keeps float's precision far from the origin through its
    // phase; one with a transform of its own is evaluated in its frame, as a pattern is.
    vec3 pigment;
    if (SCENE_HAS_PATTERNS && m.checker_frame != NO_MAP) pigment = material_pigment(m, pattern_space(pattern_at(m.checker_frame), q), vec3(0.0));
    else pigment = world ? material_pigment(m, p, m.checker_phase.xyz) : material_pigment(m, q, vec3(0.0));
    Appearance a = Appearance(pigment, n);
    // A smooth mesh shades with its interpolated vertex normals; a bump tilts that. (A mesh is
    // always placed: PLACED_OBJECTS holds where there is one.)
    if (SCENE_HAS_MESH && PLACED_OBJECTS) {
        Primitive prim = primitive_at(hit.primitive);
        if (prim.type == SHAPE_MESH && prim.p0.x != 0.0) a.normal = mesh_shading_normal(prim, hit.uv, q, frame, n);
    }
    if (SCENE_HAS_TEXTURES && m.texture_map != NO_MAP) a.pigment *= texture_color(m.texture_map, texture_uv(hit, p));
    if (!SCENE_HAS_PATTERNS) return a;
    // The colour pattern, then the bump, through one evaluation site: inlined twice, the noise
    // code made every scene with patterns slower (lavapipe), not only where they are seen.
    [[dont_unroll]] for (uint k = 0u; k < 2u; ++k) {
        uint index = k == 0u ? m.color_pattern : m.bump_pattern;
        if (index == NO_MAP) continue;
        PatternInfo pat = pattern_at(index);
        vec4 f = pattern_value(pat, pattern_space(pat, q));
        if (k == 0u) {
            a.pigment *= ramp_color(pat, f.w);
        } else {
            // The gradient in the object's coordinates, then the world's (its depth scaled alike).
            vec3 g = pattern_gradient(pat, f.xyz);
            if (PLACED_OBJECTS) g = world_gradient(frame, g) * frame.mean_scale;
            a.normal = bumped_normal(pat, g, a.normal);
        }
    }
    return a;
}

// The mirror direction of d about the shading normal, turned back above the geometric surface
// if a bump or a smooth mesh's normals tilted it below (it would otherwise start inside the object).
vec3 bounce_direction(vec3 d, vec3 shading_normal, vec3 n) {
    vec3 r = reflect(d, shading_normal);
    if (!SCENE_HAS_PATTERNS && !SCENE_HAS_MESH) return r;
    float below = dot(r, n);
    return below < 0.0 ? r - 2.0 * below * n : r;
}

#endif

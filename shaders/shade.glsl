// Local shading at a hit: ambient + per light (or area light sample) that the point sees,
// diffuse + specular. The CPU reference writes the same model in host/cpu/tracer.cpp; the
// scene format reference (docs/scene-format.md, "Shading model") states it as a formula.
#ifndef LANCER_SHADE_GLSL
#define LANCER_SHADE_GLSL

#include "lights.glsl"
#include "microfacet_material.glsl"

// p: the point in the GPU's coordinates (phase: the material's checker_phase) or in its object's (phase 0).
vec3 material_pigment(Material m, vec3 p, vec3 phase) {
    if (m.pattern == PATTERN_CHECKER) {
        // Solid 3-D checker, first colour where floor(x)+floor(y)+floor(z) is even (as POV-Ray).
        // The 1e-4 bias keeps surfaces lying on integer planes (the floor at y = 0) on one side.
        // The parity by mod, as the CPU reference's fmod: converting a sum beyond int's range
        // (a checker far finer than the scene) to int is undefined.
        // p is relative to the GPU's anchor near the camera: checker_phase puts it back in the
        // checker's period.
        vec3 cell = floor((p + phase) / m.checker_size + 1e-4);
        bool odd = mod(abs(cell.x + cell.y + cell.z), 2.0) == 1.0;
        return odd ? m.color2.rgb : m.color.rgb;
    }
    return m.color.rgb;
}

// On a transparent surface, a light sample whose unshadowed light would add less than this to the
// pixel is skipped, shadow ray and all: it cannot change an 8-bit result. Glass is mostly
// highlight, and far from its peak a highlight is nothing, but its shadow ray would cross the
// glass many times.
const float MIN_LIGHT = 1.0 / 65536.0;

// Adds the diffuse and specular light from point q of `light` (one of `count` samples) at p, if
// q is in front of the surface and p sees it. n is the geometric normal (which lights are in
// front), shading_n the one that lights the surface (n, or tilted by a bump). Shadow rays start
// at `origin`, just off the surface, inside `media` (transparent objects in the way tint rather
// than block). `scale` is what the local colour will be multiplied by on its way to the pixel.
// A microfacet material's light is pi f (N.L) times the light's (its colour is irradiance over
// pi): in `diffuse`, with `pigment` holding the indices (n1, n2) of a glass's interface.
void add_light(inout vec3 color, Material m, vec3 pigment, vec3 p, vec3 n, vec3 shading_n, vec3 view_dir, vec3 mirrored,
               vec3 origin, Light light, uint light_index, vec3 q, uint count, Media media, vec3 scale, inout float rays) {
    vec3 l = normalize(q - p);
    if (dot(n, l) <= 0.0) return;  // light behind the surface: no shadow ray needed
    bool micro = SCENE_HAS_MICROFACET && m.model != MODEL_PHONG;
    vec3 diffuse;
    float shine = 0.0;
    if (micro) {
        diffuse = MICROFACET_PI * dot(n, l) * microfacet_brdf(m, n, -view_dir, l, pigment.x, pigment.y);
    } else {
        float n_dot_l = max(0.0, dot(shading_n, l));
        diffuse = m.phong.y * n_dot_l * pigment;
        float highlight = SCENE_HAS_BLINN && m.highlight == HIGHLIGHT_BLINN ? dot(shading_n, normalize(l - view_dir)) : dot(mirrored, l);
        shine = highlight > 0.0 && m.phong.z > 0.0 ? m.phong.z * pow(highlight, m.phong.w) : 0.0;
    }
    vec3 intensity = light_intensity(light, q, p, count);
    if ((micro || (SCENE_HAS_TRANSPARENCY && is_transparent(m))) && max3(scale * (diffuse + shine) * intensity) < MIN_LIGHT) return;
    rays += 1.0;
    vec3 through = transmittance(p, origin, q, media, light_index);
    if (max3(through) <= 0.0) return;  // in the shadow of an opaque surface
    intensity *= through;
    color += diffuse * intensity;
    if (shine > 0.0) color += shine * intensity;
}

// pigment: the surface's colour there (appearance.glsl); for a microfacet material, (n1, n2). n: the geometric normal, facing the
// viewer; error: the hit's error bound (Hit.error), which sets how far off the surface shadow rays
// start; shading_n: the normal that lights the surface. view_dir is the incoming ray direction;
// `media` holds the transparent materials the incoming ray is inside; `seed` places area light
// samples (lights.glsl); `scale` is what the result will be multiplied by on its way to the pixel.
vec3 shade_local(Material m, vec3 pigment, vec3 p, vec3 n, float error, vec3 shading_n, vec3 view_dir, Media media, uint seed,
                 vec3 scale, inout float rays) {
    bool micro = SCENE_HAS_MICROFACET && m.model != MODEL_PHONG;
    if (micro && material_alpha(m) == 0.0) return vec3(0.0);  // a perfect mirror shows no point of light
    if (SCENE_HAS_TRANSPARENCY && !micro) pigment *= vec3(1.0) - m.transmission.rgb;  // the part that is not transmitted
    vec3 color = micro ? vec3(0.0) : m.phong.x * pigment * frame.ambient.rgb;
    vec3 mirrored = reflect(view_dir, shading_n);
    vec3 origin = offset_origin(p, n, error);  // shadow rays start here; shading uses p itself
    // One loop over every sample of every light (a point or spot light is one sample at its
    // position), with one call site: each inlines the shadow ray's whole intersection code. Not a
    // loop over samples inside the loop over lights: lavapipe keeps even a one-trip inner loop
    // around that much code (the teapot was 6% slower, A/B). The light is fetched once, at its
    // first sample (fetching it at every sample cost the area-light scene 5%).
    uint s = 0u;
    Light light;
    uint count = 0u;
    for (uint i = 0u; i < frame.light_count;) {
        if (s == 0u) {
            light = light_at(i);
            count = light_sample_count(light);
        }
        vec3 q = light_sample_position(light, i, s, seed);
        add_light(color, m, pigment, p, n, shading_n, view_dir, mirrored, origin, light, i, q, count, media, scale, rays);
        if (++s >= count) {
            s = 0u;
            ++i;
        }
    }
    return color;
}

#endif

#version 450
// lancer's ray tracer: one invocation per pixel, an N x N grid of camera rays, and for each an
// iterative bounce loop (no recursion) with Phong shading, shadow rays and mirror reflection.
// The CPU reference (host/cpu/) implements the same model independently, in double precision.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require

#include "layout.h"

layout(local_size_x = WORKGROUP_X, local_size_y = WORKGROUP_Y, local_size_z = 1) in;

layout(push_constant) uniform BandBlock { BandParams band; };
// rgb = linear colour, a = number of rays traced for this pixel (camera + shadow + reflection).
// Between the passes of a progressive render: rgb = the sum of the samples so far. a = -1 marks
// an invocation the driver cut short (see loop_limit_reached).
layout(std430, set = 0, binding = BINDING_OUTPUT) buffer OutputBlock { vec4 pixels[]; };

#include "common.glsl"
#include "scene.glsl"
#include "shade.glsl"
#include "appearance.glsl"

// Below this remaining weight a reflection cannot change the 8-bit result (< 1/4 of a level).
const float MIN_WEIGHT = 1.0 / 1024.0;

vec3 trace(Ray ray, inout float rays) {
    vec3 color = vec3(0.0);
    vec3 weight = vec3(1.0);
    for (uint depth = 0u; depth <= frame.max_depth; ++depth) {
        rays += 1.0;
        Hit hit;
        if (!closest_hit(ray, 0.0, hit)) {
            color += weight * frame.background.rgb;
            return color;
        }
        vec3 p = ray.origin + hit.t * ray.dir;
        vec3 n = hit.normal;
        if (dot(n, ray.dir) > 0.0) n = -n;  // two-sided surfaces
        Material m = materials[primitives[hit.primitive].material];
        Appearance look = appearance_at(m, hit, p, n);
        vec3 local = shade_local(m, look.pigment, p, n, look.normal, ray.dir, rays);
        color += weight * (1.0 - m.reflection) * local;
        weight *= m.reflection;
        if (max(weight.r, max(weight.g, weight.b)) < MIN_WEIGHT) return color;
        ray = Ray(p + ray_offset(p) * n, bounce_direction(ray.dir, look.normal, n));
    }
    // Past max_depth the reflected ray contributes black (POV-Ray's max_trace_level rule).
    return color;
}

// The ray through the continuous image position s (pixels from the top-left corner).
Ray camera_ray(vec2 s) {
    float ndc_x = 2.0 * s.x / float(frame.width) - 1.0;
    float ndc_y = 1.0 - 2.0 * s.y / float(frame.height);
    return Ray(frame.eye.xyz, normalize(frame.forward.xyz + ndc_x * frame.right.xyz + ndc_y * frame.up.xyz));
}

// Test variant: the first hit of the ray through the pixel's centre, as (t, u, v, part):
// t < 0 for a miss; (u, v) the surface's own parameters; part the patch index for Bezier
// surfaces, else -1.
layout(constant_id = SPEC_OUTPUT_HITS) const bool OUTPUT_HITS = false;

vec4 first_hit(vec2 s) {
    Hit hit;
    if (!closest_hit(camera_ray(s), 0.0, hit)) return vec4(-1.0, 0.0, 0.0, -1.0);
    return vec4(hit.t, surface_uv(hit), surface_part(hit));
}

// lavapipe (llvmpipe) ends every loop of an invocation once all its loops together have run
// 65535 iterations (its LP_MAX_TGSI_LOOP_ITERATIONS; the 8 lanes of a SIMD group share the
// count): the answers are then silently wrong. After that, any loop stops after its first
// iteration, so a loop of two iterations that runs only one shows the invocation was cut
// short. Its trip count comes from a uniform, so it cannot be unrolled away. A marked pixel
// makes the host render its band again with one sample per invocation (gpu_renderer.cpp).
layout(constant_id = SPEC_CHECK_LOOP_LIMIT) const bool CHECK_LOOP_LIMIT = false;

bool loop_limit_reached() {
    uint runs = 0u;
    for (uint i = 0u; i < frame.loop_probe; ++i) ++runs;
    return runs < frame.loop_probe;
}

void main() {
    uvec2 pixel = uvec2(gl_GlobalInvocationID.x, band.y0 + gl_GlobalInvocationID.y);
    if (pixel.x >= frame.width || gl_GlobalInvocationID.y >= band.rows || pixel.y >= frame.height) return;
    uint out_index = gl_GlobalInvocationID.y * frame.width + pixel.x;
    if (OUTPUT_HITS) {
        vec4 hit = first_hit(vec2(pixel) + 0.5);
        pixels[out_index] = CHECK_LOOP_LIMIT && loop_limit_reached() ? vec4(-1.0, 0.0, 0.0, -2.0) : hit;
        return;
    }

    float n = float(frame.samples);
    uint total = frame.samples * frame.samples;
    uint last = min(band.sample_first + band.sample_count, total);
    vec3 sum = vec3(0.0);
    float rays = 0.0;
    if (band.sample_first > 0u) {  // continue the sums of the passes before (see BandParams)
        sum = pixels[out_index].rgb;
        rays = pixels[out_index].a;
    }
    bool marked = rays < 0.0;  // an earlier pass was cut short
    for (uint k = band.sample_first; k < last; ++k) {
        uvec2 ij = uvec2(k % frame.samples, k / frame.samples);
        sum += trace(camera_ray(vec2(pixel) + (vec2(ij) + 0.5) / n), rays);
    }
    if (marked || (CHECK_LOOP_LIMIT && loop_limit_reached())) {
        pixels[out_index] = vec4(0.0, 0.0, 0.0, -1.0);
        return;
    }
    pixels[out_index] = last == total ? vec4(sum / (n * n), rays) : vec4(sum, rays);
}

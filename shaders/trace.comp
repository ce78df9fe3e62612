#version 450
// lancer's ray tracer: one invocation per pixel, an N x N grid of camera rays, and for each an
// iterative ray tree (no recursion: a loop and a small stack of pending rays) with Phong
// shading, shadow rays, mirror reflection and refraction.
// The CPU reference (host/cpu/) implements the same model independently, in double precision.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require

#include "interface.glsl"

layout(local_size_x = WORKGROUP_X, local_size_y = WORKGROUP_Y, local_size_z = 1) in;

layout(push_constant) uniform BandBlock { BandParams band; };
// The output, pixels[]: rgb = linear colour, a = number of rays traced for this pixel (camera +
// shadow + reflection). Between the passes of a progressive render: rgb = the sum of the
// samples so far. a = -1 marks an invocation the driver cut short (see loop_limit_reached), a = -3
// one whose ray broke the grids' contract (scene.glsl, grid_contract_broken).
const float CONTRACT_BROKEN = -3.0;

#include "common.glsl"
#include "fog.glsl"
#include "scene.glsl"
#include "dielectric.glsl"
#include "shade.glsl"
#include "appearance.glsl"
#include "sky.glsl"
#include "microfacet_material.glsl"
#include "photon_gather.glsl"

// The ray tree. At a transparent surface a ray splits into a reflected and a refracted ray: the
// heavier goes on at once, the lighter waits in a small stack (when the stack is full, it is
// dropped: black). Opaque surfaces only reflect, so scenes without transparency trace one path.
const uint PENDING_SIZE = 8u;
// A surface of a medium inside that same medium (a liquid's wall inside its glass) is passed
// straight through, at most this many times per path; after that the path contributes black.
const uint MAX_PASS_THROUGH = 16u;

// A ray of the tree and what it carries: the twin of the CPU tracer's Branch (host/cpu/tracer.cpp).
struct Branch {
    Ray ray;
    vec3 from;  // the surface point the ray leaves (its origin is just off it): media absorb from here
    vec3 weight;
    uint depth;
    Media media;
};

// What a hit sends on: the mirror ray's and the refracted ray's directions and weights (a weight
// below MIN_WEIGHT: no such ray).
struct Scatter {
    vec3 reflected_dir, reflected_weight;
    vec3 refracted_dir, refracted_weight;
};

// A hit's local light, whichever the model: ambient + what each light sample that the point sees
// adds (shade.glsl's shade_local), times `scale`, what it is multiplied by on its way to the
// pixel. One call for both models: lavapipe inlines each call, with its shadow rays' whole
// intersection code. look: a Phong surface's appearance (its pigment and shading normal); for a
// microfacet material the geometric normal n, and `indices` its interface's (n1, n2).
vec3 local_light(Material m, Appearance look, vec2 indices, Hit hit, vec3 p, vec3 n, Branch b, uint seed_d, inout float rays) {
    vec3 scale = b.weight * (1.0 - m.reflection);
    vec3 pigment = look.pigment;
    if (SCENE_HAS_MICROFACET && m.model != MODEL_PHONG) {
        scale = b.weight;
        pigment = vec3(indices, 0.0);
    }
    return scale * shade_local(m, pigment, p, n, hit.error, look.normal, b.ray.dir, b.media, seed_d, scale, rays);
}

// A Phong (or Blinn-Phong) surface hit by b at p (normal n toward the ray), of appearance `look`,
// with `beyond` the media past it, its local light added: adds photon mapping's gather to
// `color`, and says what it sends on. The twin of Tracer::phong_hit.
void phong_hit(Material m, Appearance look, vec3 p, vec3 n, Branch b, Media beyond, bool clear, bool sheet, inout vec3 color,
               out Scatter s) {
    vec3 scale = b.weight * (1.0 - m.reflection);
    // Photon mapping: caustics and indirect light, the diffuse BRDF k_d C' / pi times the
    // irradiance the photons estimate.
    if (SCENE_HAS_PHOTONS && m.phong.y > 0.0)
        color += scale * (m.phong.y / MICROFACET_PI) * look.pigment * (vec3(1.0) - m.transmission.rgb) * photon_irradiance(p, n);
    s.reflected_weight = b.weight * m.reflection;
    s.refracted_weight = vec3(0.0);
    s.refracted_dir = b.ray.dir;
    if (clear) {
        // Fresnel splits what the surface transmits between the mirror and the refracted ray.
        float n1 = medium_ior(innermost(b.media));
        float n2 = sheet ? m.transmission.w : medium_ior(innermost(beyond));
        // About the shading normal, as POV-Ray bends light; grazing it, all is reflected.
        vec3 bend = sheet ? n : look.normal;
        float cos_i = max(-dot(b.ray.dir, bend), 0.0);
        float cos_t;
        float f = fresnel(cos_i, n1, n2, cos_t);
        vec3 passing = b.weight * (1.0 - m.reflection) * m.transmission.rgb;
        s.reflected_weight += passing * f;
        s.refracted_weight = passing * (1.0 - f);
        if (!sheet) s.refracted_dir = crossing_direction(refraction(b.ray.dir, bend, n1 / n2, cos_i, cos_t), n);
    }
    // A bump or a smooth mesh tilts the mirror direction, and the refracted one where it can.
    s.reflected_dir = bounce_direction(b.ray.dir, look.normal, n);
}

// A metal or a glass of microfacets (microfacet_material.glsl) between media of indices (n1, n2),
// its local light added: the rays it sends on, drawn from its lobes. The twin of
// Tracer::microfacet_hit.
void microfacet_hit(Material m, vec3 n, Branch b, vec2 indices, bool sheet, uint seed_d, out Scatter s) {
    vec3 u = surface_sample_numbers(seed_d);
    s.refracted_weight = vec3(0.0);
    s.refracted_dir = b.ray.dir;
    if (is_metal(m)) {
        Scattered metal = sample_metal(m, n, -b.ray.dir, u);
        s.reflected_dir = metal.dir;
        s.reflected_weight = b.weight * metal.weight;
        return;
    }
    // A thin sheet has no inside to bend into: it reflects and transmits as a smooth one.
    Scattered mirrored, refracted;
    sample_glass(m, sheet ? 0.0 : material_alpha(m), n, -b.ray.dir, indices.x, indices.y, u, mirrored, refracted);
    s.reflected_dir = mirrored.dir;
    s.reflected_weight = b.weight * mirrored.weight;
    s.refracted_weight = b.weight * refracted.weight;
    if (!sheet) s.refracted_dir = refracted.dir;
}

// The colour seen along `ray`. `seed` identifies the camera sample (pixel and grid sample), for
// area light samples. Adds every ray traced (camera, shadow, reflected, refracted) to `rays`.
// The twin of Tracer::trace.
vec3 trace(Ray ray, uint seed, inout float rays) {
    vec3 color = vec3(0.0);
    Branch b = Branch(ray, ray.origin, vec3(1.0), 0u, no_media());
    uint passes = 0u;  // surfaces passed through on this path
    Branch pending[PENDING_SIZE];
    uint waiting = 0u;
    uint grid = DIRECTION_GRID_EYE;  // the camera ray's
    for (;;) {
        rays += 1.0;
        Hit hit;
        bool found = closest_hit(b.ray, 0.0, grid, hit);
        grid = NO_GRID;
        // Media absorb between surface points (not from the offset origin): the true thickness.
        if (SCENE_HAS_TRANSPARENCY && b.media.count > 0u) {
            b.weight *= absorption_over(innermost(b.media), found ? length(b.ray.origin + hit.t * b.ray.dir - b.from) : INFINITY);
        }
        if (SCENE_HAS_FOG) {  // the fog in front of what the ray meets, and its veil over it (Tracer::trace)
            float through = exp(-fog_depth(b.from, normalize(b.ray.dir), found ? length(b.ray.origin + hit.t * b.ray.dir - b.from) : INFINITY) * frame.fog.w);
            color += b.weight * (1.0 - through) * frame.fog.rgb;
            b.weight *= through;
        }
        bool goes_on = false;
        if (!found) {
            if (SCENE_HAS_SKY) color += b.weight * sky_color(b.ray.dir);
            else color += b.weight * frame.background.rgb;
        } else {
            vec3 p = b.ray.origin + hit.t * b.ray.dir;
            vec3 n = hit.normal;
            if (dot(n, b.ray.dir) > 0.0) n = -n;  // two-sided surfaces
            uint mat = hit_material(hit.primitive, hit.uv);
            Material m = material_at(mat);
            bool clear = SCENE_HAS_TRANSPARENCY && is_transparent(m);
            bool sheet = clear && is_thin_sheet(hit.primitive);
            Media beyond = clear && !sheet ? cross_surface(b.media, mat) : b.media;  // the media past the surface
            if (clear && !sheet && innermost(beyond) == innermost(b.media)) {
                // The same medium on both sides (a liquid's wall inside its glass): invisible.
                b.media = beyond;
                b.ray = Ray(through_surface(hit.primitive, p, n, b.ray.dir, hit.error), b.ray.dir);
                b.from = p;
                goes_on = ++passes <= MAX_PASS_THROUGH;
            } else {
                Scatter s;
                // (The model's test written out at each branch, not kept in a variable: the host's
                // dead-branch pass folds it only so, where the scene has no microfacet material.)
                Appearance look = Appearance(vec3(0.0), n);
                vec2 indices = vec2(0.0);
                if (SCENE_HAS_MICROFACET && m.model != MODEL_PHONG)
                    indices = vec2(medium_ior(innermost(b.media)), sheet ? m.transmission.w : medium_ior(innermost(beyond)));
                else
                    look = appearance_at(m, hit, p, n);
                uint seed_d = hash_u32(seed + b.depth);
                color += local_light(m, look, indices, hit, p, n, b, seed_d, rays);
                if (SCENE_HAS_MICROFACET && m.model != MODEL_PHONG) microfacet_hit(m, n, b, indices, sheet, seed_d, s);
                else phong_hit(m, look, p, n, b, beyond, clear, sheet, color, s);
                // Past max_depth the children contribute black (POV-Ray's max_trace_level rule).
                bool reflects = b.depth < frame.max_depth && max3(s.reflected_weight) >= MIN_WEIGHT;
                bool refracts = b.depth < frame.max_depth && max3(s.refracted_weight) >= MIN_WEIGHT;
                Branch reflected = Branch(Ray(offset_origin(p, n, hit.error), s.reflected_dir), p, s.reflected_weight, b.depth + 1u, b.media);
                if (refracts) {
                    Branch refracted = Branch(Ray(through_surface(hit.primitive, p, n, s.refracted_dir, hit.error), s.refracted_dir), p,
                                              s.refracted_weight, b.depth + 1u, beyond);
                    // The heavier goes on now, the lighter waits (dropped when the stack is full).
                    bool reflected_first = reflects && max3(s.reflected_weight) > max3(s.refracted_weight);
                    if (reflects && waiting < PENDING_SIZE) pending[waiting++] = reflected_first ? refracted : reflected;
                    b = reflected_first ? reflected : refracted;
                } else if (reflects) {
                    b = reflected;
                    // A camera ray's reflection in the flat mirror (see FrameParams::mirror_plane).
                    // The condition on the constant alone is one the host removes where it is false.
                    if (DIRECTION_GRIDS) {
                        if (b.depth == 1u && hit.primitive == frame.mirror_plane) grid = DIRECTION_GRID_MIRROR;
                    }
                }
                goes_on = reflects || refracts;
            }
        }
        if (goes_on) continue;
        if (!SCENE_HAS_TRANSPARENCY || waiting == 0u) break;
        b = pending[--waiting];
        passes = 0u;
    }
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

vec4 first_hit(vec2 s) {
    Hit hit;
    if (!closest_hit(camera_ray(s), 0.0, DIRECTION_GRID_EYE, hit)) return vec4(-1.0, 0.0, 0.0, -1.0);
    return vec4(hit.t, surface_uv(hit), surface_part(hit));
}

// lavapipe (llvmpipe) ends every loop of an invocation once all its loops together have run
// 65535 iterations (its LP_MAX_TGSI_LOOP_ITERATIONS; the 8 lanes of a SIMD group share the
// count): the answers are then silently wrong. After that, any loop stops after its first
// iteration, so a loop of two iterations that runs only one shows the invocation was cut
// short. Its trip count comes from a uniform, so it cannot be unrolled away. A marked pixel
// makes the host render its band again with one sample per invocation (gpu_renderer.cpp).

bool loop_limit_reached();

// Photon mapping renders one camera sample per pixel and pass (docs/scene-format.md): pass k
// takes grid sample j = k mod N^2, at the cell's centre with the seed of a plain render during
// the first N^2 passes, and from round r = k / N^2 on at a hashed place with the seed
// h(seed_j ^ h(r)). The passes of a render [first_pass, last_pass) add up in the output; the
// last divides by their number.
void photon_pass_pixel(uvec2 pixel, uint out_index) {
    uint pass = photon_params.pass;
    uint n = frame.samples;
    uint j = pass % (n * n), round = pass / (n * n);
    uint seed = hash_u32(hash_u32(hash_u32(pixel.x) ^ pixel.y) ^ j);
    vec2 offset = vec2(0.5);
    if (round > 0u) {
        seed = hash_u32(seed ^ hash_u32(round));
        uint g = hash_u32(seed);
        offset = vec2(unit_interval(g), unit_interval(hash_u32(g)));
    }
    vec3 sum = vec3(0.0);
    float rays = 0.0;
    if (pass > photon_params.first_pass) {
        sum = pixels[out_index].rgb;
        rays = pixels[out_index].a;
    }
    bool marked = rays < 0.0;
    sum += trace(camera_ray(vec2(pixel) + (vec2(uvec2(j % n, j / n)) + offset) / float(n)), seed, rays);
    if (marked || (CHECK_LOOP_LIMIT && loop_limit_reached())) {
        pixels[out_index] = vec4(0.0, 0.0, 0.0, -1.0);
        return;
    }
    if (CHECK_GRID_CONTRACT && grid_contract_broken) rays = CONTRACT_BROKEN;
    bool last = pass + 1u == photon_params.last_pass;
    pixels[out_index] = last ? vec4(sum / float(photon_params.last_pass - photon_params.first_pass), rays) : vec4(sum, rays);
}

bool loop_limit_reached() {
    uint runs = 0u;
    for (uint i = 0u; i < frame.loop_probe; ++i) ++runs;
    return runs < frame.loop_probe;
}

// The position in the 8 x 8 workgroup of invocation i, in Z order: SIMD lanes take consecutive
// invocations (lavapipe: 8 of them at 256 bits), and in Z order 8 consecutive ones are a 4 x 2
// tile, not a row of 8. Rays of a compact tile take more alike paths through the BVH and the
// patches' searches, so fewer lanes wait (docs/performance.md). A GPU's wider warps get 4 x 4
// and 8 x 4 tiles.
uvec2 z_order_position(uint i) {
    return uvec2((i & 1u) | ((i >> 1u) & 2u) | ((i >> 2u) & 4u), ((i >> 1u) & 1u) | ((i >> 2u) & 2u) | ((i >> 3u) & 4u));
}

void main() {
    uint out_index;
    uvec2 pixel;
    // The place this workgroup takes, in the band's order (BandParams::group_stride).
    uint groups = gl_NumWorkGroups.x * gl_NumWorkGroups.y;
    uint group = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * band.group_stride % groups;
    if (band.refine_count > 0u) {
        // A compact list of pixels (see BandParams). A workgroup takes consecutive entries, which
        // lie along the same edge: SIMD lanes then trace neighbouring pixels, as in a full band,
        // where a workgroup's 8 x 8 tile of the list would take 8 pieces of edge far apart.
        out_index = group * uint(WORKGROUP_X * WORKGROUP_Y) + gl_LocalInvocationIndex;
        if (out_index >= band.refine_count) return;
        uint p = refine_list[band.refine_first + out_index];
        pixel = uvec2(p % frame.width, p / frame.width);
    } else {
        uvec2 tile = uvec2(group % gl_NumWorkGroups.x, group / gl_NumWorkGroups.x);
        uvec2 cell = tile * uvec2(WORKGROUP_X, WORKGROUP_Y) + z_order_position(gl_LocalInvocationIndex);
        if (cell.x >= frame.width || cell.y >= band.rows) return;
        out_index = cell.y * frame.width + cell.x;
        pixel = uvec2(cell.x, band.y0 + cell.y);
        if (pixel.y >= frame.height) return;
    }
    if (OUTPUT_HITS) {
        vec4 hit = first_hit(vec2(pixel) + 0.5);
        pixels[out_index] = CHECK_LOOP_LIMIT && loop_limit_reached() ? vec4(-1.0, 0.0, 0.0, -2.0) : hit;
        if (CHECK_GRID_CONTRACT && grid_contract_broken) pixels[out_index].a = CONTRACT_BROKEN;
        return;
    }

    if (SCENE_HAS_PHOTONS) {
        photon_pass_pixel(pixel, out_index);
        return;
    }

    float n = float(frame.samples);
    uint total = frame.samples * frame.samples;
    uint last = min(band.sample_first + band.sample_count, total);
    vec3 sum = vec3(0.0);
    float rays = 0.0;
    bool spread = band.spread != 0u;  // only with a list (see BandParams)
    uint lo_index = band.refine_count + out_index, hi_index = 2u * band.refine_count + out_index;
    vec3 hi = vec3(-uintBitsToFloat(0x7f800000u)), lo = -hi;  // -inf, +inf
    if (band.sample_first > 0u) {  // continue the sums of the passes before (see BandParams)
        sum = pixels[out_index].rgb;
        rays = pixels[out_index].a;
        if (spread) {
            lo = pixels[lo_index].rgb;
            hi = pixels[hi_index].rgb;
        }
    }
    bool marked = rays < 0.0;  // an earlier pass was cut short
    for (uint k = band.sample_first; k < last; ++k) {
        uvec2 ij = uvec2(k % frame.samples, k / frame.samples);
        uint seed = hash_u32(hash_u32(hash_u32(pixel.x) ^ pixel.y) ^ k);
        vec3 c = trace(camera_ray(vec2(pixel) + (vec2(ij) + 0.5) / n), seed, rays);
        sum += c;
        if (spread) {
            lo = min(lo, c);
            hi = max(hi, c);
        }
    }
    if (marked || (CHECK_LOOP_LIMIT && loop_limit_reached())) {
        pixels[out_index] = vec4(0.0, 0.0, 0.0, -1.0);
        return;
    }
    if (CHECK_GRID_CONTRACT && grid_contract_broken) rays = CONTRACT_BROKEN;
    pixels[out_index] = last == total ? vec4(sum / (n * n), rays) : vec4(sum, rays);
    if (spread) {
        pixels[lo_index] = vec4(lo, 0.0);
        pixels[hi_index] = vec4(hi, 0.0);
    }
}

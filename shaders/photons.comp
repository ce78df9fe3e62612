#version 450
// The photon pass (docs/scene-format.md, "[photons]"): one invocation per photon. It picks a
// light by power, leaves it, bounces through mirrors, glass, metals and diffuse surfaces with
// Russian roulette, and appends a record to the pass's photons wherever it lands on a diffuse
// surface after its first bounce. Twin of host/cpu/photon_tracer.cpp: the same numbers from the
// same integer hash, written independently in float.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require

#include "interface.glsl"

layout(local_size_x = PHOTON_WORKGROUP, local_size_y = 1, local_size_z = 1) in;

#include "common.glsl"
#include "scene.glsl"
#include "dielectric.glsl"
#include "shade.glsl"
#include "appearance.glsl"

// A path passes through at most this many surfaces that do not show (as camera rays).
const uint MAX_PASS_THROUGH_PHOTON = 16u;

// The numbers photon `photon` of pass `pass` draws: base = h(h(h(seed) ^ pass) ^ photon), then
// number k is the top 24 bits of h(base ^ h(k)) over 2^24.
struct PhotonRandom {
    uint base;
    uint k;
};
float next_number(inout PhotonRandom rng) { return unit_interval(hash_u32(rng.base ^ hash_u32(rng.k++))); }

// Any two unit vectors perpendicular to n and to each other (as the CPU reference's tangents()).
void tangents(vec3 n, out vec3 t, out vec3 b) {
    t = normalize(abs(n.x) > 0.5 ? cross(n, vec3(0.0, 1.0, 0.0)) : cross(n, vec3(1.0, 0.0, 0.0)));
    b = cross(n, t);
}

vec3 uniform_sphere(float u1, float u2) {
    float z = 1.0 - 2.0 * u1;
    float r = sqrt(max(0.0, 1.0 - z * z));
    float phi = 2.0 * MICROFACET_PI * u2;
    return vec3(r * cos(phi), r * sin(phi), z);
}

vec3 cosine_direction(vec3 n, float u1, float u2) {
    vec3 t, b;
    tangents(n, t, b);
    float r = sqrt(u1), phi = 2.0 * MICROFACET_PI * u2;
    return normalize(r * cos(phi) * t + r * sin(phi) * b + sqrt(max(0.0, 1.0 - u1)) * n);
}

void store_photon(vec3 p, vec3 dir, vec3 power, uint map) {
    uint slot = atomicAdd(photon_counter[0], 1u);
    if (slot < photon_params.capacity) photons[slot] = Photon(vec4(p, float(map)), vec4(dir, 0.0), vec4(power, 0.0));
}

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= photon_params.count) return;
    PhotonRandom rng = PhotonRandom(hash_u32(hash_u32(hash_u32(photon_params.seed) ^ photon_params.pass) ^ index), 0u);

    // The light, by power: the first whose cumulative share exceeds u.
    float u = next_number(rng);
    uint chosen = frame.light_count - 1u;
    for (uint i = 0u; i < frame.light_count; ++i) {
        if (u < emitter_at(i).power.w) {
            chosen = i;
            break;
        }
    }
    Light light = light_at(chosen);
    Emitter emitter = emitter_at(chosen);
    vec3 power = emitter.power.rgb;
    vec3 origin = light.position.xyz;
    vec3 dir;
    if (light.type == LIGHT_SPOT) {
        float cos_outer = light.spot.x;
        float cos_theta = 1.0 - next_number(rng) * (1.0 - cos_outer);
        float phi = 2.0 * MICROFACET_PI * next_number(rng);
        float sin_theta = sqrt(max(0.0, 1.0 - cos_theta * cos_theta));
        vec3 t, b;
        tangents(light.direction.xyz, t, b);
        dir = normalize(sin_theta * (cos(phi) * t + sin(phi) * b) + cos_theta * light.direction.xyz);
        power *= spot_factor(light, dir) * emitter.cone.x;
    } else {
        if (light.type == LIGHT_AREA) {
            float a = next_number(rng) - 0.5;
            float b = next_number(rng) - 0.5;
            origin += a * light.edge_u.xyz + b * light.edge_v.xyz;
        }
        float u1 = next_number(rng);
        float u2 = next_number(rng);
        dir = uniform_sphere(u1, u2);
    }
    if (max3(power) <= 0.0) return;

    Ray ray = Ray(origin, dir);
    Media media = no_media();
    vec3 from = origin;
    bool specular_only = true;  // every bounce so far off a mirror, glass or metal
    uint bounces = 0u, passes = 0u;
    while (bounces < photon_params.max_bounces) {
        Hit hit;
        if (!closest_hit(ray, 0.0, NO_GRID, hit)) return;
        vec3 p = ray.origin + hit.t * ray.dir;
        if (SCENE_HAS_TRANSPARENCY && media.count > 0u) power *= absorption_over(innermost(media), length(p - from));
        vec3 n = hit.normal;
        if (dot(n, ray.dir) > 0.0) n = -n;  // facing the photon
        uint mat = hit_material(hit.primitive, hit.uv);
        Material m = material_at(mat);
        bool clear = SCENE_HAS_TRANSPARENCY && is_transparent(m);
        bool sheet = clear && is_thin_sheet(hit.primitive);
        Media beyond = clear && !sheet ? cross_surface(media, mat) : media;
        from = p;
        if (clear && !sheet && innermost(beyond) == innermost(media)) {
            media = beyond;  // a surface that does not show
            ray = Ray(through_surface(hit.primitive, p, n, ray.dir, hit.error), ray.dir);
            if (++passes > MAX_PASS_THROUGH_PHOTON) return;
            continue;
        }
        float n1 = medium_ior(innermost(media));
        float n2 = sheet ? m.transmission.w : medium_ior(innermost(beyond));
        vec3 wo = -ray.dir;
        vec3 weight;
        bool refracts = false;
        if (SCENE_HAS_MICROFACET && m.model != MODEL_PHONG) {
            vec3 us = vec3(next_number(rng), next_number(rng), next_number(rng));
            if (is_metal(m)) {
                Scattered s = sample_metal(m, n, wo, us);
                float keep = min(1.0, max3(s.weight));
                if (!(next_number(rng) < keep)) return;
                ray.dir = s.dir;
                weight = s.weight / keep;
            } else {
                Scattered mirrored, refracted;
                sample_glass(m, sheet ? 0.0 : material_alpha(m), n, wo, n1, n2, us, mirrored, refracted);
                float p_mirror = max3(mirrored.weight), p_refract = max3(refracted.weight);
                float sum = p_mirror + p_refract;
                if (sum > 1.0) {
                    p_mirror /= sum;
                    p_refract /= sum;
                }
                float v = next_number(rng);
                if (v < p_mirror) {
                    weight = mirrored.weight / p_mirror;
                    ray.dir = mirrored.dir;
                } else if (v - p_mirror < p_refract) {
                    weight = refracted.weight / p_refract;
                    refracts = true;
                    if (!sheet) ray.dir = refracted.dir;
                } else {
                    return;
                }
            }
        } else {
            Appearance look = appearance_at(m, hit, p, n);
            vec3 transmission = clear ? m.transmission.rgb : vec3(0.0);
            vec3 diffuse = (1.0 - m.reflection) * (vec3(1.0) - transmission) * m.phong.y * look.pigment;
            // Stored where it lands on a diffuse surface, unless straight from the light (shadow
            // rays see to that): the caustic map if every bounce was specular, else the global one.
            if (max3(diffuse) > 0.0 && bounces > 0u) store_photon(p, ray.dir, power, specular_only ? 0u : 1u);
            float cos_t = 0.0;
            vec3 bend = sheet ? n : look.normal;  // as trace.comp's phong_hit bends light
            float cos_i = max(dot(wo, bend), 0.0);
            float f = clear ? fresnel(cos_i, n1, n2, cos_t) : 0.0;
            vec3 passing = (1.0 - m.reflection) * transmission;
            vec3 w_mirror = m.reflection + passing * f;
            vec3 w_refract = passing * (1.0 - f);
            float p_mirror = max3(w_mirror), p_refract = max3(w_refract), p_diffuse = max3(diffuse);
            float sum = p_mirror + p_refract + p_diffuse;
            if (sum > 1.0) {
                p_mirror /= sum;
                p_refract /= sum;
                p_diffuse /= sum;
            }
            float v = next_number(rng);
            if (v < p_mirror) {
                weight = w_mirror / p_mirror;
                ray.dir = bounce_direction(ray.dir, look.normal, n);
            } else if ((v -= p_mirror) < p_refract) {
                weight = w_refract / p_refract;
                refracts = true;
                if (!sheet) ray.dir = crossing_direction(refraction(ray.dir, bend, n1 / n2, cos_i, cos_t), n);
            } else if (v - p_refract < p_diffuse) {
                weight = diffuse / p_diffuse;
                float u1 = next_number(rng);
                float u2 = next_number(rng);
                vec3 d = cosine_direction(look.normal, u1, u2);
                if (dot(d, n) <= 0.0) d = normalize(d - 2.0 * dot(d, n) * n);
                ray.dir = d;
                specular_only = false;
            } else {
                return;
            }
        }
        power *= weight;
        if (max3(power) <= 0.0) return;
        ++bounces;
        if (refracts) {
            media = beyond;
            ray.origin = through_surface(hit.primitive, p, n, ray.dir, hit.error);
        } else {
            ray.origin = offset_origin(p, n, hit.error);
        }
    }
}

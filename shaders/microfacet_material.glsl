// Microfacet materials at a hit (docs/scene-format.md, "Microfacet materials"): the BRDF toward
// a light, and the rays a metal or a glass sends on. Twin of host/cpu/microfacet.cpp, written
// independently in float. A microfacet material keeps its own constants in the fields Phong
// does not use (layout.h, Material): tint in color, (eta, alpha) in color2, (k, E_avg) in
// phong, the multiple-scattering colour in ms_tint, its energy table's index in energy_table.
// energy_tables hold ENERGY_TABLE_SIZE values of E(mu) per table, as float bits
// (host/optics/energy.hpp).
#ifndef LANCER_MICROFACET_MATERIAL_GLSL
#define LANCER_MICROFACET_MATERIAL_GLSL

#include "microfacet.glsl"

bool is_metal(Material m) { return m.model == MODEL_MICROFACET_METAL; }
float material_alpha(Material m) { return m.color2.w; }

// E(mu) of the material's table, linear between its 32 values.
float material_energy(Material m, float mu) {
    float x = clamp(mu, 0.0, 1.0) * float(ENERGY_TABLE_SIZE - 1u);
    uint i = min(uint(x), ENERGY_TABLE_SIZE - 2u);
    uint base = m.energy_table * ENERGY_TABLE_SIZE;
    float e0 = uintBitsToFloat(energy_table_at(base + i)), e1 = uintBitsToFloat(energy_table_at(base + i + 1u));
    return mix(e0, e1, x - float(i));
}

// The BRDF for light arriving from wi and leaving toward wo at a surface with unit normal n
// facing wo; n1 -> n2 the indices at a glass interface. 0 for smooth materials.
vec3 microfacet_brdf(Material m, vec3 n, vec3 wo, vec3 wi, float n1, float n2) {
    float alpha = material_alpha(m);
    if (alpha == 0.0) return vec3(0.0);
    mat3 to_world = basis_around(n);
    vec3 o = wo * to_world, i = wi * to_world;  // (v * M) = transpose(M) v: into the local frame
    if (o.z <= 0.0 || i.z <= 0.0) return vec3(0.0);
    float single = ggx_reflection(o, i, alpha);
    float cos_h = dot(o, normalize(o + i));
    if (!is_metal(m)) {
        float cos_t;
        return m.transmission.rgb * (single * fresnel(cos_h, n1, n2, cos_t));
    }
    vec3 f = m.color.rgb * conductor_fresnel(cos_h, m.color2.rgb, m.phong.rgb);
    float e_avg = m.phong.w;
    float ms = e_avg < 1.0 ? (1.0 - material_energy(m, o.z)) * (1.0 - material_energy(m, i.z)) / (MICROFACET_PI * (1.0 - e_avg)) : 0.0;
    return single * f + ms * vec3(m.ms_tint_r, m.ms_tint_g, m.ms_tint_b);
}

struct Scattered {
    vec3 dir;
    vec3 weight;  // f cos / pdf: 0 for no ray
};

// The ray a metal sends toward its environment for the light leaving toward wo (u: three
// numbers in [0, 1)): the mirror when smooth; else, with probability E(mu_o), a visible normal
// and the mirror about it, or else the multiple-scattering lobe drawn by the cosine.
Scattered sample_metal(Material m, vec3 n, vec3 wo, vec3 u) {
    float alpha = material_alpha(m);
    if (alpha == 0.0) return Scattered(reflect(-wo, n), m.color.rgb * conductor_fresnel(dot(wo, n), m.color2.rgb, m.phong.rgb));
    mat3 to_world = basis_around(n);
    vec3 o = wo * to_world;
    if (o.z <= 0.0) return Scattered(n, vec3(0.0));
    float single_share = material_energy(m, o.z);
    if (u.x < single_share) {
        vec3 h = sample_visible_normal(o, alpha, u.yz);
        vec3 i = reflect(-o, h);
        if (i.z <= 0.0) return Scattered(n, vec3(0.0));
        float g = smith_g2(o.z, i.z, alpha) / smith_g1(o.z, alpha);
        vec3 f = m.color.rgb * conductor_fresnel(dot(o, h), m.color2.rgb, m.phong.rgb);
        return Scattered(to_world * i, f * (g / single_share));
    }
    float r = sqrt(u.y), phi = 2.0 * MICROFACET_PI * u.z;
    vec3 i = vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.y)));
    vec3 tint = vec3(m.ms_tint_r, m.ms_tint_g, m.ms_tint_b);
    return Scattered(to_world * i, tint * ((1.0 - material_energy(m, i.z)) / (1.0 - m.phong.w)));
}

// A glass of GGX width alpha splits at one normal (n when alpha is 0, else drawn from those wo
// sees) into a mirrored and a refracted ray, from index n1 (wo's side) to n2. Each keeps
// T * (F or 1 - F) * G2 / G1 (G2 / G1 = 1 when smooth); a direction on the wrong side of the
// surface gets weight 0.
void sample_glass(Material m, float alpha, vec3 n, vec3 wo, float n1, float n2, vec3 u, out Scattered mirrored,
                  out Scattered refracted) {
    vec3 h = n;
    float g1 = 1.0;
    float cos_o = dot(wo, n);
    if (alpha > 0.0) {
        mat3 to_world = basis_around(n);
        h = to_world * sample_visible_normal(wo * to_world, alpha, u.yz);
        g1 = smith_g1(cos_o, alpha);
    }
    mirrored = Scattered(n, vec3(0.0));
    refracted = Scattered(-n, vec3(0.0));
    float cos_i = dot(wo, h);
    if (cos_i <= 0.0 || cos_o <= 0.0) return;
    float cos_t;
    float f = fresnel(cos_i, n1, n2, cos_t);
    vec3 r = reflect(-wo, h);
    float c = dot(r, n);
    if (c > 0.0) mirrored = Scattered(r, m.transmission.rgb * (f * (alpha > 0.0 ? smith_g2(cos_o, c, alpha) / g1 : 1.0)));
    if (f < 1.0) {
        vec3 t = refraction(-wo, h, n1 / n2, cos_i, cos_t);
        c = dot(t, n);
        if (c < 0.0)
            refracted = Scattered(t, m.transmission.rgb * ((1.0 - f) * (alpha > 0.0 ? smith_g2(cos_o, -c, alpha) / g1 : 1.0)));
    }
}

// The three numbers a hit draws (docs/scene-format.md): g0 = h(seed_D ^ 0x68bc21eb), g1 = h(g0),
// g2 = h(g1), each's top 24 bits over 2^24.
vec3 surface_sample_numbers(uint seed_d) {
    uint g0 = hash_u32(seed_d ^ 0x68bc21ebu);
    uint g1 = hash_u32(g0);
    return vec3(unit_interval(g0), unit_interval(g1), unit_interval(hash_u32(g1)));
}

#endif

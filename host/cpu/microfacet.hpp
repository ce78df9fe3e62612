#pragma once
// The CPU reference's microfacet materials (docs/scene-format.md, "Microfacet materials"): GGX
// metals with exact conductor Fresnel and Kulla-Conty's multiple-scattering term, and rough or
// smooth glass with exact dielectric Fresnel. What the tracer asks of them: the BRDF toward a
// light, and the directions and weights of the rays a hit spawns. The shader's twin is
// shaders/microfacet.glsl; the formulas are in optics/ggx.hpp.
#include <array>
#include <cstdint>
#include <vector>

#include "optics/energy.hpp"
#include "scene/scene.hpp"

namespace lancer::cpu {

// What a microfacet material needs besides its keys: its energy table (rough metals).
struct MicrofacetTerms {
    double alpha = 0.0;
    optics::EnergyTable energy;  // single-scattering albedo of a white conductor of this alpha
    dvec3 ms_tint{0.0};          // the multiple-scattering lobe's colour (optics/energy.hpp)
};

// One per material of a scene (empty for Phong materials).
std::vector<MicrofacetTerms> microfacet_terms(const Scene& scene);

// The BRDF (1/sr, per channel) of a microfacet material for light arriving from wi and leaving
// toward wo, at a surface with unit normal n facing wo (all unit vectors, pointing away from the
// surface). Metals: single scattering, tinted Fresnel, plus the multiple-scattering lobe. Glass:
// the reflection at an interface from index n1 (wo's side) to n2. 0 for smooth materials
// (a mirror reflects no light from a point toward any other given point).
dvec3 microfacet_brdf(const Material& m, const MicrofacetTerms& terms, const dvec3& n, const dvec3& wo,
                      const dvec3& wi, double n1, double n2);

// A sampled direction and what the ray along it carries: weight = f cos / pdf (the
// fraction of that direction's radiance that leaves toward wo). Zero weight: no ray.
struct Scattered {
    dvec3 dir{0.0};
    dvec3 weight{0.0};
};

// The ray a metal sends toward its environment, for the light leaving toward wo: the mirror
// direction when smooth, else a microfacet normal drawn from those wo sees (or the multiple-
// scattering lobe, drawn by the cosine, with probability 1 - E(cos theta_o)). u: three numbers in
// [0, 1).
Scattered sample_metal(const Material& m, const MicrofacetTerms& terms, const dvec3& n, const dvec3& wo,
                       const std::array<double, 3>& u);

// Glass of GGX width alpha splits at one microfacet normal (n itself when alpha is 0) into a
// reflected and a refracted ray, from index n1 (wo's side) to n2; both weights include the
// material's transmission (as for Phong glass). A refracted weight of 0 is total internal
// reflection, or a direction on the wrong side of the surface.
struct GlassSplit {
    Scattered reflected;
    Scattered refracted;
};
GlassSplit sample_glass(const Material& m, double alpha, const dvec3& n, const dvec3& wo, double n1, double n2,
                        const std::array<double, 3>& u);

// The three numbers a hit's sampling uses, from its depth's seed (docs/scene-format.md:
// g = h(seed_D ^ 0x68bc21eb), then h(g), h(h(g)), each's top 24 bits / 2^24).
std::array<double, 3> surface_sample_numbers(std::uint32_t seed_d);

}  // namespace lancer::cpu

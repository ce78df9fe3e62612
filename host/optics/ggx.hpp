#pragma once
// The Trowbridge-Reitz (GGX) microfacet model in double precision: the distribution of normals,
// Smith's masking with the height-correlated shadowing-masking term, sampling of the normals
// a direction sees (Heitz 2018), and Fresnel's equations for conductors (complex index of
// refraction). Used by the CPU reference and by the host to tabulate what the GPU needs
// (optics/energy.hpp); shaders/microfacet.glsl implements the same formulas independently.
//
// Directions are in the surface's local frame: the normal is +z, and every direction points
// away from the surface (wo toward the viewer, wi toward the light). alpha is the GGX width,
// roughness squared.
#include <glm/vec3.hpp>

namespace lancer::optics {

using glm::dvec3;

// D(m): the density of microfacet normals with cosine cos_m to the mean normal (per steradian
// of m, normalised so that the projected area integrates to 1: the integral of D(m) cos_m is 1).
double ggx_distribution(double cos_m, double alpha);

// Smith's Lambda for a direction with cosine cos_theta to the normal; G1 = 1 / (1 + Lambda).
double ggx_lambda(double cos_theta, double alpha);
double smith_g1(double cos_theta, double alpha);
// The height-correlated masking-shadowing term 1 / (1 + Lambda(wo) + Lambda(wi)).
double smith_g2(double cos_o, double cos_i, double alpha);

// A microfacet normal drawn from the normals that wo sees, D_wo(m) = G1(wo) max(0, wo.m) D(m) / wo.z,
// from two numbers in [0, 1) (Heitz, "Sampling the GGX distribution of visible normals", 2018).
dvec3 sample_visible_normal(const dvec3& wo, double alpha, double u1, double u2);

// The single-scattering GGX reflection BRDF with Fresnel factor 1: D G2 / (4 cos_o cos_i); 0
// when either direction is below the surface.
double ggx_reflection(const dvec3& wo, const dvec3& wi, double alpha);

// Unpolarised reflectance of a conductor of complex index eta + i k (relative to the medium
// the light comes from) at an angle of incidence with cosine cos_i, per channel.
dvec3 conductor_fresnel(double cos_i, const dvec3& eta, const dvec3& k);

}  // namespace lancer::optics

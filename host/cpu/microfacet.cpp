#include "cpu/microfacet.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/constants.hpp"
#include "cpu/dielectric.hpp"
#include "cpu/lights.hpp"
#include "optics/ggx.hpp"

namespace lancer::cpu {
namespace {

// An orthonormal basis with n as +z (Duff et al., "Building an orthonormal basis, revisited").
struct Frame {
    dvec3 t, b, n;
    explicit Frame(const dvec3& normal) : n(normal) {
        double sign = n.z >= 0.0 ? 1.0 : -1.0;
        double a = -1.0 / (sign + n.z);
        double c = n.x * n.y * a;
        t = dvec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
        b = dvec3(c, sign + n.y * n.y * a, -n.y);
    }
    dvec3 to_local(const dvec3& v) const { return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)}; }
    dvec3 to_world(const dvec3& v) const { return v.x * t + v.y * b + v.z * n; }
};

dvec3 mirror_about(const dvec3& w, const dvec3& m) { return 2.0 * glm::dot(w, m) * m - w; }

}  // namespace

std::vector<MicrofacetTerms> microfacet_terms(const Scene& scene) {
    std::vector<MicrofacetTerms> out(scene.materials.size());
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        if (!m.microfacet()) continue;
        out[i].alpha = m.alpha();
        if (!m.conductor || m.alpha() == 0.0) continue;
        out[i].energy = optics::ggx_energy(m.alpha());
        dvec3 f_avg = optics::conductor_fresnel_average(m.conductor->eta, m.conductor->k) * m.color;
        out[i].ms_tint = optics::multiple_scattering_tint(f_avg, out[i].energy.e_avg);
    }
    return out;
}

dvec3 microfacet_brdf(const Material& m, const MicrofacetTerms& terms, const dvec3& n, const dvec3& wo,
                      const dvec3& wi, double n1, double n2) {
    if (terms.alpha == 0.0) return dvec3(0.0);
    Frame frame(n);
    dvec3 o = frame.to_local(wo), i = frame.to_local(wi);
    if (o.z <= 0.0 || i.z <= 0.0) return dvec3(0.0);
    double single = optics::ggx_reflection(o, i, terms.alpha);
    double cos_h = glm::dot(o, glm::normalize(o + i));
    if (!m.conductor) return m.transmission * (single * fresnel(cos_h, n1, n2).reflectance);
    dvec3 f = m.color * optics::conductor_fresnel(cos_h, m.conductor->eta, m.conductor->k);
    const optics::EnergyTable& e = terms.energy;
    double ms = e.e_avg < 1.0 ? (1.0 - e.at(o.z)) * (1.0 - e.at(i.z)) / (kPi * (1.0 - e.e_avg)) : 0.0;
    return single * f + ms * terms.ms_tint;
}

Scattered sample_metal(const Material& m, const MicrofacetTerms& terms, const dvec3& n, const dvec3& wo,
                       const std::array<double, 3>& u) {
    const optics::ComplexIor& ior = *m.conductor;
    if (terms.alpha == 0.0) {
        dvec3 r = mirror_about(wo, n);
        return {r, m.color * optics::conductor_fresnel(glm::dot(wo, n), ior.eta, ior.k)};
    }
    Frame frame(n);
    dvec3 o = frame.to_local(wo);
    if (o.z <= 0.0) return {};
    double single_share = terms.energy.at(o.z);  // the single-scattering lobe's part of the albedo
    if (u[0] < single_share) {
        dvec3 h = optics::sample_visible_normal(o, terms.alpha, u[1], u[2]);
        dvec3 i = mirror_about(o, h);
        if (i.z <= 0.0) return {};
        // f cos / pdf for visible normals: F G2 / G1(wo); divided by the lobe's probability.
        double g = optics::smith_g2(o.z, i.z, terms.alpha) / optics::smith_g1(o.z, terms.alpha);
        dvec3 f = m.color * optics::conductor_fresnel(glm::dot(o, h), ior.eta, ior.k);
        return {frame.to_world(i), f * g / single_share};
    }
    // The multiple-scattering lobe by the cosine: f cos / pdf = pi f_ms, over its probability.
    double r = std::sqrt(u[1]), phi = 2.0 * kPi * u[2];
    dvec3 i(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u[1])));
    const optics::EnergyTable& e = terms.energy;
    dvec3 weight = terms.ms_tint * (1.0 - e.at(i.z)) / (1.0 - e.e_avg);  // pi f_ms / (1 - E(mu_o))
    return {frame.to_world(i), weight};
}

GlassSplit sample_glass(const Material& m, double alpha, const dvec3& n, const dvec3& wo, double n1, double n2,
                        const std::array<double, 3>& u) {
    dvec3 h = n;
    double g1 = 1.0;
    Frame frame(n);
    if (alpha > 0.0) {
        dvec3 o = frame.to_local(wo);
        if (o.z <= 0.0) return {};
        h = frame.to_world(optics::sample_visible_normal(o, alpha, u[1], u[2]));
        g1 = optics::smith_g1(o.z, alpha);
    }
    double cos_i = glm::dot(wo, h);
    if (cos_i <= 0.0) return {};
    Fresnel f = fresnel(cos_i, n1, n2);
    GlassSplit split;
    // Each ray keeps G2 / G1 of what it leaves (1 on a smooth surface); a direction on the wrong
    // side of the surface is lost (the masking that G2 accounts for).
    auto kept = [&](const dvec3& dir, bool reflected) {
        double c = glm::dot(dir, n);
        if (reflected ? c <= 0.0 : c >= 0.0) return 0.0;
        return alpha > 0.0 ? optics::smith_g2(glm::dot(wo, n), std::abs(c), alpha) / g1 : 1.0;
    };
    dvec3 r = mirror_about(wo, h);
    split.reflected = {r, m.transmission * f.reflectance * kept(r, true)};
    if (f.reflectance < 1.0) {
        dvec3 t = refract(-wo, h, n1 / n2, cos_i, f.cos_t);
        split.refracted = {t, m.transmission * (1.0 - f.reflectance) * kept(t, false)};
    }
    return split;
}

std::array<double, 3> surface_sample_numbers(std::uint32_t seed_d) {
    std::uint32_t g = hash_u32(seed_d ^ 0x68bc21ebu);
    std::uint32_t g2 = hash_u32(g);
    return {unit_interval(g), unit_interval(g2), unit_interval(hash_u32(g2))};
}

}  // namespace lancer::cpu

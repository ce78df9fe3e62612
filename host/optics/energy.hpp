#pragma once
// What a single bounce of the GGX model loses, for Kulla and Conty's multiple-scattering term
// ("Revisiting physically based shading at Imageworks", 2017). A white (Fresnel 1) GGX conductor
// reflects only E(mu) of the light arriving at cos theta = mu in one bounce; the rest bounces
// between microfacets before leaving. The term
//
//     f_ms(wo, wi) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),   E_avg = 2 int E(mu) mu dmu,
//
// is symmetric (reciprocal) and returns exactly that missing 1 - E(mu_o), so a lossless
// conductor reflects everything at every roughness. A coloured conductor scales it by
// F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), F_avg its hemispherical mean Fresnel reflectance.
//
// E is tabulated per roughness by quadrature over the visible normals, in double; both backends
// read the same table (the CPU reference directly, the GPU from a buffer).
#include <array>

#include <glm/vec3.hpp>

namespace lancer::optics {

struct EnergyTable {
    static constexpr int kSize = 32;  // E at mu = i / (kSize - 1), linear between
    std::array<double, kSize> e{};
    double e_avg = 1.0;  // 2 int E(mu) mu dmu of the piecewise linear E, exactly

    double at(double mu) const;  // E(mu), mu clamped to [0, 1]
};

// The table of a white GGX conductor of width alpha (> 0); computed once per alpha per process.
EnergyTable ggx_energy(double alpha);

// The multiple-scattering lobe's colour factor F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) for a
// conductor of hemispherical mean reflectance f_avg.
glm::dvec3 multiple_scattering_tint(const glm::dvec3& f_avg, double e_avg);

// 2 int F(mu) mu dmu of a conductor's Fresnel reflectance.
glm::dvec3 conductor_fresnel_average(const glm::dvec3& eta, const glm::dvec3& k);

}  // namespace lancer::optics

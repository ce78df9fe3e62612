// The microfacet model against what it must satisfy whatever the parameters: GGX's normal
// distribution integrates to 1 over the projected area, the visible normals to 1 over the
// hemisphere; sampling them reproduces the BRDF's own integral; a lossless metal reflects
// everything at every roughness and angle (white furnace), a lossy one less; the BRDF is
// reciprocal; conductor Fresnel has the textbook limits, and the named metals their known
// colours at normal incidence.
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "cpu/microfacet.hpp"
#include "cpu/dielectric.hpp"
#include "optics/energy.hpp"
#include "optics/ggx.hpp"
#include "optics/metals.hpp"

namespace lancer {
namespace {

using glm::dvec3;

const double kRoughnesses[] = {0.05, 0.1, 0.25, 0.5, 0.75, 1.0};

dvec3 from_angles(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// int over the hemisphere of g(w) dw, midpoint rule in (t, phi) with cos theta = 1 - t^2: as
// fine in theta near the normal as elsewhere, where narrow lobes peak.
template <typename G>
double hemisphere_integral(G g, int n_t = 400, int n_phi = 200) {
    double sum = 0.0;
    for (int i = 0; i < n_t; ++i) {
        double t = (i + 0.5) / n_t;
        double theta = std::acos(1.0 - t * t);
        double row = 0.0;
        for (int j = 0; j < n_phi; ++j) row += g(from_angles(theta, 2.0 * kPi * (j + 0.5) / n_phi));
        sum += 2.0 * t * row;
    }
    return sum * (1.0 / n_t) * (2.0 * kPi / n_phi);
}

Material metal(const std::string& preset, double roughness, dvec3 tint = dvec3(1.0)) {
    Material m;
    m.model = Model::Microfacet;
    m.roughness = roughness;
    m.conductor = optics::metal_preset(preset);
    m.color = tint;
    return m;
}

cpu::MicrofacetTerms terms_of(const Material& m) {
    Scene scene;
    scene.materials.push_back(m);
    return cpu::microfacet_terms(scene)[0];
}

TEST(Ggx, NormalDistributionCoversTheProjectedAreaOnce) {
    for (double r : kRoughnesses) {
        double alpha = r * r;
        // The peak of the narrow distributions needs a finer grid near the normal: integrate in
        // mu^2 = 1 - s with s concentrated near 0 by a substitution s = t^4.
        double sum = 0.0;
        const int n = 200000;
        for (int i = 0; i < n; ++i) {
            double t = (i + 0.5) / n;
            double s = t * t * t * t, ds = 4.0 * t * t * t / n;  // s = 1 - mu^2
            double mu = std::sqrt(1.0 - s);
            // dw = dmu dphi, dmu = ds / (2 mu); the integrand D(mu) mu is independent of phi.
            sum += optics::ggx_distribution(mu, alpha) * mu * ds / (2.0 * mu) * 2.0 * kPi;
        }
        EXPECT_NEAR(sum, 1.0, 1e-6) << "roughness " << r;
    }
}

TEST(Ggx, VisibleNormalsIntegrateToOneForEveryDirection) {
    for (double r : {0.25, 0.5, 1.0}) {
        double alpha = r * r;
        for (double mu_o : {0.2, 0.6, 1.0}) {
            dvec3 wo = from_angles(std::acos(mu_o), 0.3);
            double g1 = optics::smith_g1(mu_o, alpha);
            double total = hemisphere_integral([&](const dvec3& m) {
                return g1 * std::max(0.0, glm::dot(wo, m)) * optics::ggx_distribution(m.z, alpha) / wo.z;
            }, 600, 300);
            EXPECT_NEAR(total, 1.0, 2e-3) << "roughness " << r << ", cos theta_o " << mu_o;
        }
    }
}

// The energy table comes from sampling visible normals; the BRDF's own integral, by brute
// quadrature over directions, must agree: a wrong sampler or a wrong G2 breaks this.
TEST(Ggx, SampledAlbedoEqualsTheIntegralOfTheBrdf) {
    for (double r : {0.25, 0.5, 0.75, 1.0}) {
        double alpha = r * r;
        optics::EnergyTable table = optics::ggx_energy(alpha);
        // (The quadrature cannot resolve the narrowest lobe at grazing angles.)
        for (int i : r >= 0.5 ? std::vector<int>{4, 12, 20, 31} : std::vector<int>{12, 20, 31}) {
            double mu_o = double(i) / (optics::EnergyTable::kSize - 1);
            dvec3 wo = from_angles(std::acos(mu_o), 0.0);
            double brute = hemisphere_integral([&](const dvec3& wi) { return optics::ggx_reflection(wo, wi, alpha) * wi.z; },
                                               600, 400);
            EXPECT_NEAR(table.e[i], brute, 2e-3) << "roughness " << r << ", cos theta_o " << mu_o;
        }
        EXPECT_LT(table.e_avg, 1.0);
    }
    // Rougher surfaces lose more to multiple scattering.
    EXPECT_GT(optics::ggx_energy(0.1 * 0.1).e_avg, optics::ggx_energy(0.5 * 0.5).e_avg);
    EXPECT_GT(optics::ggx_energy(0.5 * 0.5).e_avg, optics::ggx_energy(1.0).e_avg);
}

// White furnace on the BRDF: a lossless metal under uniform light returns all of it, at every
// roughness and angle; gold returns less in every channel.
TEST(Microfacet, LosslessMetalReflectsEverythingAtEveryRoughness) {
    const dvec3 n(0.0, 0.0, 1.0);
    for (double r : kRoughnesses) {
        Material m = metal("perfect", r);
        cpu::MicrofacetTerms terms = terms_of(m);
        for (double mu_o : {0.15, 0.4, 0.7, 1.0}) {
            dvec3 wo = from_angles(std::acos(mu_o), 1.0);
            // By quadrature of the BRDF (fine enough for roughness >= 0.25; the narrow lobes by
            // the sampler below)...
            if (r >= 0.25) {
                double albedo = hemisphere_integral([&](const dvec3& wi) {
                    return cpu::microfacet_brdf(m, terms, n, wo, wi, 1.0, 1.0).r * wi.z;
                }, 500, 300);
                EXPECT_NEAR(albedo, 1.0, 3e-3) << "roughness " << r << ", cos theta_o " << mu_o;
            }
            // ...and as the tracer uses it: the mean weight of sampled rays.
            std::mt19937 rng(7);
            std::uniform_real_distribution<double> u01(0.0, 1.0);
            double sum = 0.0, sum2 = 0.0;
            const int samples = 40000;
            for (int s = 0; s < samples; ++s) {
                cpu::Scattered sc = cpu::sample_metal(m, terms, n, wo, {u01(rng), u01(rng), u01(rng)});
                sum += sc.weight.g;
                sum2 += sc.weight.g * sc.weight.g;
            }
            double mean = sum / samples;
            double error = std::sqrt((sum2 / samples - mean * mean) / samples);
            EXPECT_NEAR(mean, 1.0, std::max(4.0 * error, 2e-3)) << "roughness " << r << ", cos theta_o " << mu_o;
        }
    }
}

TEST(Microfacet, LossyMetalsReflectLessThanAllInEveryChannel) {
    const dvec3 n(0.0, 0.0, 1.0);
    for (const char* preset : {"gold", "silver", "copper", "aluminium"}) {
        for (double r : {0.1, 0.5, 1.0}) {
            Material m = metal(preset, r);
            cpu::MicrofacetTerms terms = terms_of(m);
            dvec3 wo = from_angles(0.5, 0.0);
            std::mt19937 rng(3);
            std::uniform_real_distribution<double> u01(0.0, 1.0);
            dvec3 sum(0.0);
            const int samples = 50000;
            for (int s = 0; s < samples; ++s) sum += cpu::sample_metal(m, terms, n, wo, {u01(rng), u01(rng), u01(rng)}).weight;
            dvec3 mean = sum / double(samples);
            for (int c = 0; c < 3; ++c) {
                EXPECT_LT(mean[c], 0.99) << preset << " roughness " << r << " channel " << c;
                EXPECT_GT(mean[c], 0.1) << preset << " roughness " << r << " channel " << c;
            }
        }
    }
    // A tint scales what a lossless metal returns.
    Material tinted = metal("perfect", 0.5, dvec3(0.5));
    cpu::MicrofacetTerms terms = terms_of(tinted);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    double sum = 0.0;
    for (int s = 0; s < 50000; ++s)
        sum += cpu::sample_metal(tinted, terms, dvec3(0, 0, 1), from_angles(0.4, 0.0), {u01(rng), u01(rng), u01(rng)}).weight.r;
    EXPECT_LT(sum / 50000, 0.55);
    EXPECT_GT(sum / 50000, 0.25);
}

TEST(Microfacet, BrdfIsReciprocal) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const dvec3 n = glm::normalize(dvec3(0.3, 0.9, -0.2));
    for (const char* preset : {"gold", "perfect"}) {
        for (double r : kRoughnesses) {
            Material m = metal(preset, r);
            cpu::MicrofacetTerms terms = terms_of(m);
            Material glass;
            glass.model = Model::Microfacet;
            glass.roughness = r;
            glass.transmission = dvec3(1.0);
            glass.ior = 1.5;
            cpu::MicrofacetTerms glass_terms = terms_of(glass);
            for (int i = 0; i < 200; ++i) {
                auto direction = [&] {
                    dvec3 d = glm::normalize(dvec3(u01(rng) - 0.5, u01(rng) - 0.5, u01(rng) - 0.5));
                    return glm::dot(d, n) < 0.0 ? -d : d;
                };
                dvec3 a = direction(), b = direction();
                dvec3 ab = cpu::microfacet_brdf(m, terms, n, a, b, 1.0, 1.0);
                dvec3 ba = cpu::microfacet_brdf(m, terms, n, b, a, 1.0, 1.0);
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(ab[c], ba[c], 1e-12 * std::max(1.0, ab[c])) << preset << " " << r;
                EXPECT_GT(ab.r, 0.0);
                dvec3 gab = cpu::microfacet_brdf(glass, glass_terms, n, a, b, 1.0, 1.5);
                dvec3 gba = cpu::microfacet_brdf(glass, glass_terms, n, b, a, 1.0, 1.5);
                EXPECT_NEAR(gab.r, gba.r, 1e-12 * std::max(1.0, gab.r));
            }
        }
    }
}

TEST(ConductorFresnel, TextbookLimits) {
    for (double eta : {0.2, 1.0, 1.7}) {
        for (double k : {0.0, 0.5, 3.0}) {
            double f0 = ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k);
            EXPECT_NEAR(optics::conductor_fresnel(1.0, dvec3(eta), dvec3(k)).r, f0, 1e-12) << eta << " " << k;
            // Grazing light is all reflected, except where there is no interface (index 1).
            double grazing = eta == 1.0 && k == 0.0 ? 0.0 : 1.0;
            EXPECT_NEAR(optics::conductor_fresnel(0.0, dvec3(eta), dvec3(k)).r, grazing, 1e-12) << eta << " " << k;
        }
    }
    // k = 0 is a dielectric: the same as the glass Fresnel, at every angle.
    for (double c = 0.05; c <= 1.0; c += 0.05)
        EXPECT_NEAR(optics::conductor_fresnel(c, dvec3(1.5), dvec3(0.0)).r, cpu::fresnel(c, 1.0, 1.5).reflectance, 1e-12);
    // A purely imaginary index absorbs nothing: everything is reflected.
    for (double c = 0.0; c <= 1.0; c += 0.1)
        EXPECT_NEAR(optics::conductor_fresnel(c, optics::metal_preset("perfect")->eta, optics::metal_preset("perfect")->k).g,
                    1.0, 1e-12);
}

// Linear reflectance at normal incidence, as tabulated by Hoffman ("Physics and math of
// shading", SIGGRAPH 2015 course: gold 1.00 0.71 0.29, silver 0.95 0.93 0.88, copper 0.95 0.64
// 0.54, aluminium 0.91 0.92 0.92): the presets reproduce each to within 0.1.
TEST(ConductorFresnel, NamedMetalsHaveTheirColours) {
    const std::pair<const char*, dvec3> known[] = {{"gold", {1.00, 0.71, 0.29}},
                                                   {"silver", {0.95, 0.93, 0.88}},
                                                   {"copper", {0.95, 0.64, 0.54}},
                                                   {"aluminium", {0.91, 0.92, 0.92}}};
    for (const auto& [name, f0] : known) {
        auto ior = optics::metal_preset(name);
        ASSERT_TRUE(ior) << name;
        dvec3 f = optics::conductor_fresnel(1.0, ior->eta, ior->k);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], f0[c], 0.1) << name << " channel " << c;
    }
    EXPECT_FALSE(optics::metal_preset("unobtainium"));
}

TEST(Microfacet, SmoothGlassSplitsByFresnelAndRoughGlassConservesEnergy) {
    Material glass;
    glass.model = Model::Microfacet;
    glass.transmission = dvec3(1.0);
    glass.ior = 1.5;
    const dvec3 n(0.0, 0.0, 1.0);
    dvec3 wo = from_angles(0.7, 0.0);
    cpu::GlassSplit smooth = cpu::sample_glass(glass, 0.0, n, wo, 1.0, 1.5, {0.5, 0.5, 0.5});
    double f = cpu::fresnel(std::cos(0.7), 1.0, 1.5).reflectance;
    EXPECT_NEAR(smooth.reflected.weight.r, f, 1e-12);
    EXPECT_NEAR(smooth.refracted.weight.r, 1.0 - f, 1e-12);
    EXPECT_NEAR(glm::length(smooth.refracted.dir - cpu::refract(-wo, n, 1.0 / 1.5, std::cos(0.7), std::sqrt(1.0 - std::pow(std::sin(0.7) / 1.5, 2)))), 0.0, 1e-12);
    // Rough: reflected + refracted never exceed what came in, and lose little when smooth-ish.
    for (double r : kRoughnesses) {
        std::mt19937 rng(13);
        std::uniform_real_distribution<double> u01(0.0, 1.0);
        double sum = 0.0;
        const int samples = 50000;
        for (int s = 0; s < samples; ++s) {
            cpu::GlassSplit g = cpu::sample_glass(glass, r * r, n, wo, 1.0, 1.5, {u01(rng), u01(rng), u01(rng)});
            EXPECT_LE(g.reflected.weight.r + g.refracted.weight.r, 1.0 + 1e-12);
            sum += g.reflected.weight.r + g.refracted.weight.r;
        }
        EXPECT_LE(sum / samples, 1.0);
        EXPECT_GT(sum / samples, r <= 0.1 ? 0.99 : 0.8) << "roughness " << r;
    }
}

}  // namespace
}  // namespace lancer

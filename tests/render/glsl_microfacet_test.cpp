// shaders/microfacet.glsl run on the Vulkan device against the double-precision model
// (host/optics/ggx.cpp) at the same inputs: the distribution, masking, the sampled visible
// normals and conductor Fresnel agree to float accuracy over random directions, roughnesses and
// complex indices. (The render tests check the same maths through whole images, statistically.)
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "optics/ggx.hpp"
#include "optics/metals.hpp"
#include "support/gpu_kernel.hpp"

namespace lancer {
namespace {

using glm::dvec3;

// Per case, 4 vec4 in: (wo, alpha), (wi, eta), (u1, u2, k, 0); 4 vec4 out.
const char* kKernel = R"(#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "interface.glsl"
layout(local_size_x = 1) in;
#include "microfacet.glsl"
void main() {
    uint i = gl_GlobalInvocationID.x;
    vec4 a = pixels[8u * i], b = pixels[8u * i + 1u], c = pixels[8u * i + 2u];
    vec3 wo = a.xyz, wi = b.xyz;
    float alpha = a.w;
    pixels[8u * i + 4u] = vec4(ggx_distribution(normalize(wo + wi).z, alpha), smith_g1(wo.z, alpha),
                             smith_g2(wo.z, wi.z, alpha), ggx_reflection(wo, wi, alpha));
    pixels[8u * i + 5u] = vec4(sample_visible_normal(wo, alpha, c.xy), 0.0);
    pixels[8u * i + 6u] = vec4(conductor_fresnel_channel(wo.z, b.w, c.z), conductor_fresnel_channel(wi.z, b.w, c.z), 0.0, 0.0);
    mat3 frame = basis_around(normalize(wi));
    pixels[8u * i + 7u] = vec4(dot(frame[0], frame[1]), dot(frame[0], frame[2]), length(frame[0]) - 1.0, length(frame[1]) - 1.0);
}
)";

TEST(GlslMicrofacetOnDevice, AgreesWithTheDoublePrecisionModel) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const int cases = 512;
    std::vector<glm::vec4> io(cases * 8, glm::vec4(0.0f));
    float* data = &io[0].x;
    struct Case {
        dvec3 wo, wi;
        double alpha, eta, k, u1, u2;
    };
    std::vector<Case> in;
    auto upper = [&] {
        double z = 0.02 + 0.98 * u01(rng), phi = 6.283185307179586 * u01(rng), r = std::sqrt(1.0 - z * z);
        // Through float, so that both sides see the same numbers.
        return dvec3(glm::vec3(glm::normalize(dvec3(r * std::cos(phi), r * std::sin(phi), z))));
    };
    for (int i = 0; i < cases; ++i) {
        double roughness = 0.01 + 0.99 * u01(rng);
        Case c{upper(), upper(), double(float(roughness * roughness)), double(float(0.05 + 2.0 * u01(rng))),
               double(float(5.0 * u01(rng))), double(float(u01(rng))), double(float(u01(rng)))};
        if (i % 16 == 0) c.eta = 0.0, c.k = 1.0;  // the perfect mirror
        in.push_back(c);
        float* d = &data[32 * i];
        d[0] = float(c.wo.x), d[1] = float(c.wo.y), d[2] = float(c.wo.z), d[3] = float(c.alpha);
        d[4] = float(c.wi.x), d[5] = float(c.wi.y), d[6] = float(c.wi.z), d[7] = float(c.eta);
        d[8] = float(c.u1), d[9] = float(c.u2), d[10] = float(c.k);
    }
    std::vector<glm::vec4> result = test::GpuKernel(kKernel).run(io, cases);
    const float* out = &result[0].x;
    auto near = [](double got, double want, double rel) { return std::abs(got - want) <= rel * std::max(1.0, std::abs(want)); };
    for (int i = 0; i < cases; ++i) {
        const Case& c = in[i];
        const float* o = &out[32 * i + 16];
        dvec3 h = glm::normalize(c.wo + c.wi);
        // The peak of a narrow lobe is steep in cos_m: compare relatively, with float's epsilon
        // amplified by 1 / alpha^2 at most.
        double d = optics::ggx_distribution(h.z, c.alpha);
        EXPECT_TRUE(near(o[0], d, 2e-4 + 2e-7 / (c.alpha * c.alpha))) << i << ": D " << o[0] << " vs " << d;
        EXPECT_TRUE(near(o[1], optics::smith_g1(c.wo.z, c.alpha), 1e-5)) << i;
        EXPECT_TRUE(near(o[2], optics::smith_g2(c.wo.z, c.wi.z, c.alpha), 1e-5)) << i;
        double f = optics::ggx_reflection(c.wo, c.wi, c.alpha);
        EXPECT_TRUE(near(o[3], f, 2e-4 + 2e-7 / (c.alpha * c.alpha))) << i << ": f " << o[3] << " vs " << f;
        dvec3 m = optics::sample_visible_normal(c.wo, c.alpha, c.u1, c.u2);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[32 * i + 20 + k], m[k], 2e-4) << i << " normal " << k;
        // Fresnel's complex square root and quotients: 2e-5 on lavapipe, 2.4e-5 measured on NVIDIA's
        // driver (whose division and square root may be 2.5 ulps off, as Vulkan allows).
        EXPECT_NEAR(out[32 * i + 24], optics::conductor_fresnel(c.wo.z, dvec3(c.eta), dvec3(c.k)).r, 5e-5) << i;
        EXPECT_NEAR(out[32 * i + 25], optics::conductor_fresnel(c.wi.z, dvec3(c.eta), dvec3(c.k)).r, 5e-5) << i;
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(out[32 * i + 28 + k], 0.0, 1e-5) << i << " basis " << k;
    }
}

}  // namespace
}  // namespace lancer

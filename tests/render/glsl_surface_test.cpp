// The emitted GLSL run on the Vulkan device: S, dS/du and dS/dv computed by the shader agree
// with the double-precision Dual evaluation to float accuracy, for the classic surfaces and for
// an expression that uses every function. (The unit tests only compile the code; this checks
// what it computes, derivative rules included.)
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/gpu_kernel.hpp"
#include "surface/expr/evaluate.hpp"
#include "gpu/shaders/glsl_emitter.hpp"
#include "unit/surface_fixtures.hpp"

namespace lancer {
namespace {

using surface::Dual;
using surface::ParametricSurface;

// Runs surf() at each (u, v) on the device; returns P, Pu, Pv per point (12 floats with padding).
std::vector<float> run_on_device(const std::string& function, const std::vector<std::pair<float, float>>& uvs) {
    const std::string source = "#version 450\n#extension GL_GOOGLE_include_directive : require\n"
                               "#extension GL_EXT_control_flow_attributes : require\n#include \"interface.glsl\"\n"
                               "layout(local_size_x = 1) in;\n" +
                               function +
                               "void main() {\n"
                               "    uint i = gl_GlobalInvocationID.x;\n"
                               "    vec3 P, Pu, Pv;\n"
                               "    surf(pixels[4u * i].xy, P, Pu, Pv);\n"
                               "    pixels[4u * i + 1u] = vec4(P, 0.0);\n"
                               "    pixels[4u * i + 2u] = vec4(Pu, 0.0);\n"
                               "    pixels[4u * i + 3u] = vec4(Pv, 0.0);\n"
                               "}\n";
    std::vector<glm::vec4> io(uvs.size() * 4, glm::vec4(0.0f));
    for (std::size_t i = 0; i < uvs.size(); ++i) io[4 * i] = glm::vec4(uvs[i].first, uvs[i].second, 0.0f, 0.0f);
    io = test::GpuKernel(source).run(io, static_cast<std::uint32_t>(uvs.size()));
    std::vector<float> data(io.size() * 4);
    std::memcpy(data.data(), io.data(), data.size() * sizeof(float));
    return data;
}

// Compares the device's results with Dual<double> at the same (float) parameters. Float
// rounding of a value of size m costs about 1e-7 m per operation; derivatives are compared
// relative to the size of the largest partial.
void expect_device_matches(const ParametricSurface& s, const std::string& what, double tolerance = 2e-5) {
    std::mt19937 rng(81);
    std::uniform_real_distribution<double> unit(0.02, 0.98);
    std::vector<std::pair<float, float>> uvs;
    for (int i = 0; i < 64; ++i)
        uvs.emplace_back(static_cast<float>(s.u0 + (s.u1 - s.u0) * unit(rng)),
                         static_cast<float>(s.v0 + (s.v1 - s.v0) * unit(rng)));
    std::vector<float> out = run_on_device(gpu::emit_glsl_surface(s.x, s.y, s.z, "surf"), uvs);
    const surface::Expr* xyz[] = {&s.x, &s.y, &s.z};
    for (std::size_t i = 0; i < uvs.size(); ++i) {
        double u = uvs[i].first, v = uvs[i].second;
        double scale_p = 0.0, scale_d = 0.0;
        Dual<double> d[3];
        for (int k = 0; k < 3; ++k) {
            d[k] = surface::evaluate(*xyz[k], Dual<double>::variable_u(u), Dual<double>::variable_v(v));
            scale_p = std::max(scale_p, std::abs(d[k].v));
            scale_d = std::max({scale_d, std::abs(d[k].du), std::abs(d[k].dv)});
        }
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(out[16 * i + 4 + k], d[k].v, tolerance * (1.0 + scale_p)) << what << " P at " << u << ", " << v;
            EXPECT_NEAR(out[16 * i + 8 + k], d[k].du, tolerance * (1.0 + scale_d)) << what << " Pu at " << u << ", " << v;
            EXPECT_NEAR(out[16 * i + 12 + k], d[k].dv, tolerance * (1.0 + scale_d)) << what << " Pv at " << u << ", " << v;
        }
    }
}

TEST(GlslSurfaceOnDevice, ClassicSurfacesMatchTheDualEvaluation) {
    for (const auto& spec : test::classic_surfaces()) expect_device_matches(test::make_surface(spec), spec.name);
}

TEST(GlslSurfaceOnDevice, EveryFunctionsDerivativeMatches) {
    // Each coordinate mixes several functions with arguments kept inside their domains.
    ParametricSurface s;
    s.u0 = 0.1;
    s.u1 = 0.9;
    s.v0 = 0.2;
    s.v1 = 0.8;
    s.x = surface::parse_expression(
        "sin(u*v) + cos(u+v) + tan(0.5*u) + asin(0.5*v) + acos(0.4*u) + atan(u-v) + atan2(v, u - 0.5) "
        "+ sinh(u) + cosh(v) + tanh(u*v)",
        {});
    s.y = surface::parse_expression(
        "asinh(u) + acosh(1.5 + v) + atanh(0.5*u) + exp(u - v) + exp2(v) + log(u + v) + log2(1 + u) + log10(2 + v) "
        "+ sqrt(u*v) + cbrt(u - 2*v)",
        {});
    s.z = surface::parse_expression(
        "sqr(u - v) + abs(u - 2*v) + pow(u, v) + u^v + min(u, v^2) + max(u, v^2) + hypot(u, v) + u^3 + u^-2 "
        "+ v^2.5 + u^7 + u^-5 + u/(v + 1) + 2^u",
        {});
    expect_device_matches(s, "all functions", 5e-5);
}

}  // namespace
}  // namespace lancer

// The GLSL generated for implicit surfaces, run on the Vulkan device: f, its derivative along a
// direction and its gradient agree with the double-precision Dual evaluation to float accuracy,
// and the interval code (shaders/interval.glsl) encloses f and its derivative along every piece
// of ray it is given, for the classic surfaces and for expressions that use every function.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "gpu/gpu_renderer.hpp"
#include "support/gpu_kernel.hpp"
#include "support/test_support.hpp"
#include "surface/expr/evaluate.hpp"
#include "gpu/shaders/glsl_emitter.hpp"
#include "surface/expr/parser.hpp"
#include "surface/implicit_surface.hpp"

namespace lancer {
namespace {

using surface::Dual;

// Runs `code` (functions and main(), reading and writing pixels[]) as a test kernel: `data`
// holds 4 floats per vec4 of pixels[].
std::vector<float> run_compute(const std::string& code, const std::vector<float>& data, std::uint32_t invocations) {
    const std::string source = "#version 450\n#extension GL_GOOGLE_include_directive : require\n"
                               "#extension GL_EXT_control_flow_attributes : require\n#include \"interface.glsl\"\n"
                               "layout(local_size_x = 1) in;\n" +
                               code;
    std::vector<glm::vec4> io(data.size() / 4);
    for (std::size_t i = 0; i < io.size(); ++i) io[i] = glm::vec4(data[4 * i], data[4 * i + 1], data[4 * i + 2], data[4 * i + 3]);
    std::vector<glm::vec4> out = test::GpuKernel(source).run(io, invocations);
    std::vector<float> result(out.size() * 4);
    for (std::size_t i = 0; i < out.size(); ++i)
        for (int k = 0; k < 4; ++k) result[4 * i + k] = out[i][k];
    return result;
}

struct Case {
    const char* name;
    const char* text;
    glm::dvec3 lo, hi;  // where the rays' pieces stay (inside every function's domain)
    bool library_functions = false;  // beyond +, -, *, /, sqrt and integer powers
};

const Case kCases[] = {
    {"sphere", "x^2 + y^2 + z^2 - 1", glm::dvec3(-1.5), glm::dvec3(1.5)},
    {"torus", "(x^2 + y^2 + z^2 + 1 - 0.35^2)^2 - 4*(x^2 + z^2)", glm::dvec3(-1.5), glm::dvec3(1.5)},
    {"barth", "4*(2.618034*x^2 - y^2)*(2.618034*y^2 - z^2)*(2.618034*z^2 - x^2) - 4.236068*(x^2 + y^2 + z^2 - 1)^2",
     glm::dvec3(-1.5), glm::dvec3(1.5)},
    {"gyroid", "sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)", glm::dvec3(-7.0), glm::dvec3(7.0), true},
    {"high powers", "x^7 - y^-3 + z^12 - (x - y)^9 + (x*y*z)^-2", glm::dvec3(0.3), glm::dvec3(1.4)},
    {"functions 1", "sin(x*y) + cos(x+z) + tan(0.5*x) + asin(0.5*y) + acos(0.4*z) + atan(x-y) + atan2(y, x - 0.5) "
                    "+ sinh(x) + cosh(y) + tanh(x*z)", glm::dvec3(0.2), glm::dvec3(0.8), true},
    {"functions 2", "asinh(x) + acosh(1.5 + y) + atanh(0.5*z) + exp(x - y) + exp2(z) + log(x + y) + log2(1 + z) "
                    "+ log10(2 + y) + sqrt(x*y) + cbrt(x - 2*z)", glm::dvec3(0.2), glm::dvec3(0.8), true},
    {"functions 3", "sqr(x - y) + abs(x - 2*z) + pow(x, y) + x^z + min(x, y^2) + max(z, y^2) + hypot(x, y) + x^3 "
                    "+ y^-2 + z^2.5 + x/(z + 1) + 2^x", glm::dvec3(0.2), glm::dvec3(0.8), true},
};

// Per invocation, 5 vec4s: in (o, a), (d, b); out (F, dF) over [a, b], (gradient at o, f(o)),
// (f's derivative along d at o, 0, 0, 0), and with doubles (F in double over [a, b], F in double
// at o) rounded outward to float.
const char* kMain = R"(
void main() {
    uint i = 6u * gl_GlobalInvocationID.x;
    vec3 o = pixels[i].xyz, d = pixels[i + 1u].xyz;
    vec2 s = vec2(pixels[i].w, pixels[i + 1u].w);
    vec2 f, df;
    test_interval(o, d, s, f, df);
    pixels[i + 2u] = vec4(f, df);
    float dd;
    float value = test(o, d, dd);
    pixels[i + 3u] = vec4(test_gradient(o), value);
    pixels[i + 4u] = vec4(dd, 0.0, 0.0, 0.0);
#if LANCER_FLOAT64
    pixels[i + 5u] = vec4(i_flt(test_at_a_point(dvec3(o), dvec3(d), dvec2(s))),
                          i_flt(test_at_a_point(dvec3(o), dvec3(d), dvec2(0.0))));
#endif
}
)";

struct Piece {
    glm::vec3 o, d;
    float a, b;
};

class GlslImplicitOnDevice : public testing::TestWithParam<Case> {};

TEST_P(GlslImplicitOnDevice, ValuesDerivativesAndEnclosures) {
    const Case& c = GetParam();
    surface::ImplicitSurface s;
    s.f = surface::parse_expression(c.text, {}, surface::kImplicitVariables);
    const surface::Expr* f[] = {&s.f};
    s.program = surface::compile_program(f);
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal;
    const double widths[] = {1e-6, 1e-4, 1e-2, 0.1, 0.5};
    std::vector<Piece> pieces;
    while (pieces.size() < 200) {
        glm::dvec3 o = c.lo + (c.hi - c.lo) * glm::dvec3(unit(rng), unit(rng), unit(rng));
        glm::dvec3 d = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
        double w = widths[pieces.size() % 5] * glm::length(c.hi - c.lo);
        double a = -w * unit(rng);
        glm::dvec3 p0 = o + a * d, p1 = o + (a + w) * d;
        if (glm::any(glm::lessThan(glm::min(p0, p1), c.lo)) || glm::any(glm::greaterThan(glm::max(p0, p1), c.hi))) continue;
        pieces.push_back({glm::vec3(o), glm::vec3(d), float(a), float(a + w)});
    }
    std::vector<float> data(pieces.size() * 24, 0.0f);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const Piece& p = pieces[i];
        float* v = &data[24 * i];
        v[0] = p.o.x, v[1] = p.o.y, v[2] = p.o.z, v[3] = p.a;
        v[4] = p.d.x, v[5] = p.d.y, v[6] = p.d.z, v[7] = p.b;
    }
    const bool float64 = test::gpu_renderer().context().float64();
    std::vector<float> out = run_compute(fmt::format("#define LANCER_FLOAT64 {}\n#include \"interval.glsl\"\n", float64 ? 1 : 0) +
                                             gpu::emit_glsl_implicit(s.f, "test", float64) + kMain,
                                         data, static_cast<std::uint32_t>(pieces.size()));
    int samples = 0;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const Piece& p = pieces[i];
        const float* v = &out[24 * i];
        const glm::dvec3 o(p.o), d(p.d);
        // Point values at o: float against double, relative to the sizes involved.
        surface::ImplicitPoint at_o = surface::evaluate_implicit(s, o);
        double scale = 1.0 + std::abs(at_o.f) + glm::length(at_o.gradient);
        EXPECT_NEAR(v[15], at_o.f, 1e-4 * scale) << c.name << " f at piece " << i;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[12 + k], at_o.gradient[k], 1e-4 * scale) << c.name << " gradient " << k;
        EXPECT_NEAR(v[16], glm::dot(at_o.gradient, d), 1e-4 * scale) << c.name << " derivative along d";
        // The enclosures hold f and its derivative at every sampled point of the piece.
        const double lo = v[8], hi = v[9], dlo = v[10], dhi = v[11];
        // ... and are tight on the shortest pieces (a loose enclosure would only cost time, but
        // one that is always [-inf, inf] would hide a broken rule).
        if (i % 5 == 0) {
            EXPECT_LE(hi - lo, 1e-2 * scale) << c.name << " piece " << i;  // asin and acos have 2e-3 margins
        }
        // In double, f at o is known to float's last bits where only arithmetic is involved (the
        // library functions are float's: 2e-3 again).
        const double point_lo = v[22], point_hi = v[23], dlo64 = v[20], dhi64 = v[21];
        if (float64) {
            const double slack = 1e-12 * (1.0 + std::abs(at_o.f));
            EXPECT_TRUE(point_lo - slack <= at_o.f && at_o.f <= point_hi + slack)
                << c.name << " piece " << i << ": f(o) " << at_o.f << " outside [" << point_lo << ", " << point_hi << "]";
            EXPECT_LE(point_hi - point_lo, (c.library_functions ? 1e-2 : 1e-6) * scale) << c.name << " piece " << i;
        }
        for (int k = 0; k <= 32; ++k) {
            double t = p.a + (double(p.b) - p.a) * k / 32.0;
            surface::ImplicitPoint q = surface::evaluate_implicit(s, o + t * d);
            double dq = glm::dot(q.gradient, d);
            double slack_f = 1e-12 * (1.0 + std::abs(q.f)), slack_d = 1e-12 * (1.0 + std::abs(dq));
            EXPECT_TRUE(lo - slack_f <= q.f && q.f <= hi + slack_f)
                << c.name << " piece " << i << " s " << t << ": f " << q.f << " outside [" << lo << ", " << hi << "]";
            EXPECT_TRUE(dlo - slack_d <= dq && dq <= dhi + slack_d)
                << c.name << " piece " << i << " s " << t << ": f' " << dq << " outside [" << dlo << ", " << dhi << "]";
            if (float64) {
                EXPECT_TRUE(dlo64 - slack_f <= q.f && q.f <= dhi64 + slack_f)
                    << c.name << " piece " << i << " s " << t << ": f " << q.f << " outside the double [" << dlo64 << ", "
                    << dhi64 << "]";
            }
            ++samples;
        }
    }
    EXPECT_EQ(samples, 200 * 33);
}

INSTANTIATE_TEST_SUITE_P(Expressions, GlslImplicitOnDevice, testing::ValuesIn(kCases), [](const auto& info) {
    std::string name = info.param.name;
    std::replace(name.begin(), name.end(), ' ', '_');
    return name;
});

// Each function of shaders/interval.glsl on this device, against double precision: over 2048
// point intervals and 2048 short ones across its argument range, the result holds the exact
// values (the function's own rounding on the device included, which is what its margin is for).
struct LibraryCase {
    const char* call;  // GLSL of the interval function of `a`
    double (*exact)(double);
    double lo, hi;
};

const LibraryCase kLibrary[] = {
    {"i_sin(a)", [](double x) { return std::sin(x); }, -20, 20},
    {"i_cos(a)", [](double x) { return std::cos(x); }, -20, 20},
    {"i_tan(a)", [](double x) { return std::tan(x); }, -1.5, 1.5},
    {"i_asin(a)", [](double x) { return std::asin(x); }, -1, 1},
    {"i_acos(a)", [](double x) { return std::acos(x); }, -1, 1},
    {"i_atan(a)", [](double x) { return std::atan(x); }, -30, 30},
    {"i_atan2(a, vec2(0.7))", [](double x) { return std::atan2(x, 0.7); }, -30, 30},
    {"i_atan2(vec2(0.7), a)", [](double x) { return std::atan2(0.7, x); }, -30, 30},
    {"i_sinh(a)", [](double x) { return std::sinh(x); }, -8, 8},
    {"i_cosh(a)", [](double x) { return std::cosh(x); }, -8, 8},
    {"i_tanh(a)", [](double x) { return std::tanh(x); }, -8, 8},
    {"i_asinh(a)", [](double x) { return std::asinh(x); }, -30, 30},
    {"i_acosh(a)", [](double x) { return std::acosh(x); }, 1, 30},
    {"i_atanh(a)", [](double x) { return std::atanh(x); }, -0.99, 0.99},
    {"i_exp(a)", [](double x) { return std::exp(x); }, -30, 30},
    {"i_exp2(a)", [](double x) { return std::exp2(x); }, -30, 30},
    {"i_log(a)", [](double x) { return std::log(x); }, 1e-4, 1e4},
    {"i_log2(a)", [](double x) { return std::log2(x); }, 1e-4, 1e4},
    {"i_log10(a)", [](double x) { return std::log10(x); }, 1e-4, 1e4},
    {"i_sqrt(a)", [](double x) { return std::sqrt(x); }, 0, 1e4},
    {"i_cbrt(a)", [](double x) { return std::cbrt(x); }, -1e3, 1e3},
    {"i_powc(a, 2.5)", [](double x) { return std::pow(x, 2.5); }, 0, 30},
    {"i_powc(a, -0.7)", [](double x) { return std::pow(x, -0.7); }, 1e-3, 30},
    {"i_powr(a, vec2(1.7))", [](double x) { return std::pow(x, 1.7); }, 1e-3, 30},
    {"i_powr(vec2(1.7), a)", [](double x) { return std::pow(1.7, x); }, -20, 20},
    {"i_div(vec2(1.0), a)", [](double x) { return 1.0 / x; }, 0.01, 100},
    {"i_hypot(a, vec2(0.3))", [](double x) { return std::hypot(x, 0.3); }, -30, 30},
};

TEST(GlslIntervalLibrary, EveryFunctionEnclosesTheExactValues) {
    const int n = 4096;
    for (const LibraryCase& c : kLibrary) {
        std::vector<float> data(4 * n);
        std::mt19937 rng(41);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (int i = 0; i < n; ++i) {
            double a = c.lo + (c.hi - c.lo) * unit(rng);
            double b = i % 2 ? a : std::min(c.hi, a + (c.hi - c.lo) * 1e-3 * unit(rng));
            data[4 * i] = float(a);
            data[4 * i + 1] = std::max(float(a), float(b));
        }
        std::vector<float> out = run_compute(std::string("#include \"interval.glsl\"\nvoid main() {\n"
                                                               "    uint i = gl_GlobalInvocationID.x;\n"
                                                               "    vec2 a = pixels[i].xy;\n    pixels[i].zw = ") +
                                                       c.call + ";\n}\n",
                                                   data, n);
        int outside = 0;
        for (int i = 0; i < n; ++i) {
            const float* v = &out[4 * i];
            for (int k = 0; k <= 8; ++k) {
                double x = v[0] + (double(v[1]) - v[0]) * k / 8.0, y = c.exact(x);
                if (!(v[2] <= y && y <= v[3])) {
                    if (++outside <= 3)
                        std::printf("  %s: [%.9g, %.9g] at %.9g gives [%.9g, %.9g], exact %.9g\n", c.call, v[0], v[1], x, v[2],
                                    v[3], y);
                }
            }
        }
        EXPECT_EQ(outside, 0) << c.call;
    }
}

}  // namespace
}  // namespace lancer

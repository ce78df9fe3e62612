// The GLSL emitter: its output compiles (glslang, as the renderer will compile it) for every
// surface and every function, carries no user text, and prints floats that read back exactly.
#include <cstdlib>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "gpu/shaders/shader_compiler.hpp"
#include "surface/expr/functions.hpp"
#include "gpu/shaders/glsl_emitter.hpp"
#include "surface/expr/parser.hpp"
#include "unit/surface_fixtures.hpp"

namespace lancer::surface {
namespace {

// Compiles `function` (which defines `surf`) inside a minimal compute shader that calls it.
void compile_with(const std::string& function) {
    const std::string source =
        "#version 450\n"
        "layout(local_size_x = 1) in;\n"
        "layout(std430, binding = 0) buffer Out { vec4 data[]; };\n" +
        function +
        "void main() {\n"
        "    vec3 P, Pu, Pv;\n"
        "    surf(vec2(data[0].x, data[0].y), P, Pu, Pv);\n"
        "    data[1] = vec4(P, 0.0); data[2] = vec4(Pu, 0.0); data[3] = vec4(Pv, 0.0);\n"
        "}\n";
    auto tree = [&](const std::string& name) -> std::optional<std::string> {
        if (name == "trace.comp") return source;
        return std::nullopt;
    };
    auto spirv = gpu::compile_compute(tree, "trace.comp");
    EXPECT_FALSE(spirv.empty());
}

std::string emit(const std::string& x, const std::string& y, const std::string& z, const Constants& params = {}) {
    return gpu::emit_glsl_surface(parse_expression(x, params), parse_expression(y, params), parse_expression(z, params),
                             "surf");
}

TEST(GlslEmitter, ClassicSurfacesCompile) {
    for (const auto& spec : test::classic_surfaces()) {
        std::string glsl = emit(spec.x, spec.y, spec.z, spec.params);
        SCOPED_TRACE(spec.name + ":\n" + glsl);
        EXPECT_NO_THROW(compile_with(glsl));
        EXPECT_NE(glsl.find("void surf(vec2 uv, out vec3 P, out vec3 Pu, out vec3 Pv)"), std::string::npos);
    }
}

TEST(GlslEmitter, EveryFunctionAndPowerCompiles) {
    std::string x = "0";
    for (const auto& f : function_table()) {
        x += " + " + std::string(f.name) + (f.arity == 1 ? "(0.25*u + 0.5*v + 0.1)" : "(0.25*u + 1.5, v + 0.75)");
    }
    std::string y = "u^0 + u^1 + u^2 + u^3 + u^4 + u^5 + u^6 + u^7 + u^-1 + u^-3 + u^-6 + u^0.5 + u^v + 2^u + u^-0.5";
    std::string z = "-u + u - v + 2*u/v - -v + 1/(u + 2) + (u*v)/(u+v) + 3";
    std::string glsl = emit(x, y, z);
    SCOPED_TRACE(glsl);
    EXPECT_NO_THROW(compile_with(glsl));
}

TEST(GlslEmitter, ConstantAndPlainVariableCoordinatesCompile) {
    std::string glsl = emit("u", "v", "2.5");
    SCOPED_TRACE(glsl);
    EXPECT_NO_THROW(compile_with(glsl));
    EXPECT_NE(glsl.find("P = vec3(uv.x, uv.y, 2.5);"), std::string::npos);
}

TEST(GlslEmitter, SharedSubexpressionsAreComputedOnce) {
    std::string glsl = emit("(1 + 0.35*cos(v))*cos(u)", "(1 + 0.35*cos(v))*sin(u)", "0.35*sin(v)");
    std::size_t first = glsl.find("cos(uv.y)");
    ASSERT_NE(first, std::string::npos);
    // cos(v) appears once as a value; sin(v) once as a value and once in cos's derivative.
    EXPECT_EQ(glsl.find("= cos(uv.y)", first + 1), std::string::npos) << glsl;
}

TEST(GlslEmitter, NoUserTextReachesTheShader) {
    Constants params{{"secret_radius", 1.25}, {"evil", 2.0}};
    std::string glsl = emit("secret_radius*cos(u)", "evil*sin(u)", "v", params);
    EXPECT_EQ(glsl.find("secret"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("evil"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("1.25"), std::string::npos) << glsl;
    EXPECT_THROW(gpu::emit_glsl_surface(parse_expression("u", {}), parse_expression("u", {}), parse_expression("u", {}),
                                   "surf(); } void x("),
                 std::invalid_argument);
    EXPECT_THROW(gpu::emit_glsl_surface(parse_expression("u", {}), parse_expression("u", {}), parse_expression("u", {}),
                                   "gl_surf"),
                 std::invalid_argument);
}

TEST(GlslEmitter, FloatsReadBackExactly) {
    EXPECT_EQ(gpu::glsl_float(2.0), "2.0");
    EXPECT_EQ(gpu::glsl_float(0.5), "0.5");
    EXPECT_EQ(gpu::glsl_float(-1.5), "(-1.5)");
    EXPECT_EQ(gpu::glsl_float(1e-5), "9.99999975e-06");
    EXPECT_EQ(gpu::glsl_float(1e300), "uintBitsToFloat(0x7f800000u)");
    EXPECT_EQ(gpu::glsl_float(-1e300), "uintBitsToFloat(0xff800000u)");
    for (double value : {0.1, 1.0 / 3.0, 3.14159265358979, 123456789.0, 6.02e23, 1.17549435e-38, 2e-40, -7.25e-3}) {
        std::string s = gpu::glsl_float(value);
        if (s.front() == '(') s = s.substr(2, s.size() - 3);
        EXPECT_EQ(std::strtof(s.c_str(), nullptr), static_cast<float>(std::abs(value))) << s;
        EXPECT_NE(s.find_first_of(".e"), std::string::npos) << s;
    }
}

}  // namespace
}  // namespace lancer::surface

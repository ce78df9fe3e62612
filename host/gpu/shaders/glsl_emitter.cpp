#include "gpu/shaders/glsl_emitter.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "gpu/shaders/glsl_interval_emitter.hpp"
#include "surface/expr/program.hpp"

namespace lancer::gpu {
namespace {

bool is_glsl_identifier(const std::string& s) {
    auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (s.empty() || !letter(s[0]) || s.rfind("gl_", 0) == 0) return false;
    for (char c : s)
        if (!letter(c) && !(c >= '0' && c <= '9')) return false;
    return true;
}

// a^m for an integer m >= 0 as GLSL: products for small m, pow(abs(a), m) otherwise (with the
// sign restored for odd m), because GLSL's pow is undefined for negative bases.
std::string integer_power(const std::string& a, int m) {
    if (m == 0) return "1.0";
    if (m <= 4) {
        std::string s = a;
        for (int i = 1; i < m; ++i) s += " * " + a;
        return "(" + s + ")";
    }
    if (m % 2 == 0) return fmt::format("pow(abs({}), {})", a, glsl_float(m));
    return fmt::format("({} * pow(abs({}), {}))", a, a, glsl_float(m - 1));
}

// How the emitted code names the variables and their derivatives: the GLSL expression of each
// variable's value and of its derivative (its gradient, or its derivative along a direction), and
// the type of derivatives.
struct VariableCode {
    std::vector<std::string> value;
    std::vector<std::string> derivative;
    std::string type;  // "vec2", "vec3" or "float"
};

// Forward-mode differentiation: the value of every node and its derivative, as GLSL statements.
class GlslEmitter {
public:
    GlslEmitter(const surface::Program& program, VariableCode variables)
        : program_(program), variables_(std::move(variables)), value_(program.nodes.size()),
          gradient_(program.nodes.size()) {}

    // The statements, then value(i) and grad(i) name each node's results.
    std::string body() {
        for (std::size_t i = 0; i < program_.nodes.size(); ++i) emit(static_cast<int>(i));
        return out_;
    }
    const std::string& value(int i) const { return value_[i]; }
    // The derivative of node i as an expression (zero for constants).
    std::string grad(int i) const { return gradient_[i].empty() ? zero() : gradient_[i]; }

private:
    std::string zero() const { return variables_.type == "float" ? "0.0" : variables_.type + "(0.0)"; }
    bool varies(int i) const { return !gradient_[i].empty(); }

    void define(int i, const std::string& value) {
        value_[i] = fmt::format("t{}", i);
        out_ += fmt::format("    float t{} = {};\n", i, value);
    }
    void define_gradient(int i, const std::string& gradient) {
        gradient_[i] = fmt::format("g{}", i);
        out_ += fmt::format("    {} g{} = {};\n", variables_.type, i, gradient);
    }
    // A unary function f with f'(a) = k: gradient k * ga.
    void unary(int i, const std::string& value, const std::string& k) {
        const surface::Node& n = program_.nodes[i];
        define(i, value);
        if (varies(n.a)) define_gradient(i, fmt::format("({}) * {}", k, gradient_[n.a]));
    }

    void emit(int i) {
        const surface::Node& n = program_.nodes[i];
        const std::string a = n.a >= 0 ? value_[n.a] : "";
        const std::string b = n.b >= 0 ? value_[n.b] : "";
        const std::string t = fmt::format("t{}", i);
        const std::string ga = n.a >= 0 ? grad(n.a) : "", gb = n.b >= 0 ? grad(n.b) : "";
        const bool va = n.a >= 0 && varies(n.a), vb = n.b >= 0 && varies(n.b);
        switch (n.op) {
            case surface::Op::Constant: value_[i] = glsl_float(n.value); return;
            case surface::Op::Variable: {
                auto k = static_cast<std::size_t>(n.value);
                value_[i] = variables_.value.at(k);
                gradient_[i] = variables_.derivative.at(k);
                return;
            }
            case surface::Op::Add:
            case surface::Op::Sub: {
                const char* sign = n.op == surface::Op::Add ? "+" : "-";
                define(i, fmt::format("{} {} {}", a, sign, b));
                if (va && vb) define_gradient(i, fmt::format("{} {} {}", ga, sign, gb));
                else if (va) gradient_[i] = ga;
                else if (vb) define_gradient(i, n.op == surface::Op::Add ? gb : "-" + gb);
                return;
            }
            case surface::Op::Neg:
                define(i, "-" + a);
                if (va) define_gradient(i, "-" + ga);
                return;
            case surface::Op::Mul:
                define(i, fmt::format("{} * {}", a, b));
                if (va && vb) define_gradient(i, fmt::format("{} * {} + {} * {}", ga, b, a, gb));
                else if (va) define_gradient(i, fmt::format("{} * {}", ga, b));
                else if (vb) define_gradient(i, fmt::format("{} * {}", a, gb));
                return;
            case surface::Op::Div:
                define(i, fmt::format("{} / {}", a, b));
                if (va || vb) define_gradient(i, fmt::format("({} - {} * {}) / {}", ga, t, gb, b));
                return;
            case surface::Op::PowInt: {
                int m = static_cast<int>(n.value);
                if (m == 0) {
                    value_[i] = "1.0";
                    return;
                }
                if (m > 0) return unary(i, integer_power(a, m), fmt::format("{} * {}", glsl_float(m), integer_power(a, m - 1)));
                return unary(i, "1.0 / " + integer_power(a, -m),
                             fmt::format("{} / {}", glsl_float(m), integer_power(a, 1 - m)));
            }
            case surface::Op::PowConst:
                return unary(i, fmt::format("pow({}, {})", a, glsl_float(n.value)),
                             fmt::format("{} * pow({}, {})", glsl_float(n.value), a, glsl_float(n.value - 1.0)));
            case surface::Op::Pow:
                define(i, fmt::format("pow({}, {})", a, b));
                if (va || vb) define_gradient(i, fmt::format("{} * ({} * log({}) + {} * {} / {})", t, gb, a, b, ga, a));
                return;
            case surface::Op::Sqr: return unary(i, fmt::format("{} * {}", a, a), "2.0 * " + a);
            case surface::Op::Sqrt: return unary(i, fmt::format("sqrt({})", a), "0.5 / " + t);
            case surface::Op::Cbrt:
                return unary(i, fmt::format("sign({}) * pow(abs({}), {})", a, a, glsl_float(1.0 / 3.0)),
                             fmt::format("1.0 / (3.0 * {} * {})", t, t));
            case surface::Op::Exp: return unary(i, fmt::format("exp({})", a), t);
            case surface::Op::Exp2: return unary(i, fmt::format("exp2({})", a), fmt::format("{} * {}", t, glsl_float(std::log(2.0))));
            case surface::Op::Log: return unary(i, fmt::format("log({})", a), "1.0 / " + a);
            case surface::Op::Log2: return unary(i, fmt::format("log2({})", a), fmt::format("{} / {}", glsl_float(1.0 / std::log(2.0)), a));
            case surface::Op::Log10:
                return unary(i, fmt::format("log({}) * {}", a, glsl_float(1.0 / std::log(10.0))),
                             fmt::format("{} / {}", glsl_float(1.0 / std::log(10.0)), a));
            case surface::Op::Sin: return unary(i, fmt::format("sin({})", a), fmt::format("cos({})", a));
            case surface::Op::Cos: return unary(i, fmt::format("cos({})", a), fmt::format("-sin({})", a));
            case surface::Op::Tan: return unary(i, fmt::format("tan({})", a), fmt::format("1.0 + {} * {}", t, t));
            case surface::Op::Asin: return unary(i, fmt::format("asin({})", a), fmt::format("1.0 / sqrt(1.0 - {} * {})", a, a));
            case surface::Op::Acos: return unary(i, fmt::format("acos({})", a), fmt::format("-1.0 / sqrt(1.0 - {} * {})", a, a));
            case surface::Op::Atan: return unary(i, fmt::format("atan({})", a), fmt::format("1.0 / (1.0 + {} * {})", a, a));
            case surface::Op::Atan2:
                define(i, fmt::format("atan({}, {})", a, b));
                if (va || vb)
                    define_gradient(i, fmt::format("({} * {} - {} * {}) / ({} * {} + {} * {})", b, ga, a, gb, a, a, b, b));
                return;
            case surface::Op::Sinh: return unary(i, fmt::format("sinh({})", a), fmt::format("cosh({})", a));
            case surface::Op::Cosh: return unary(i, fmt::format("cosh({})", a), fmt::format("sinh({})", a));
            case surface::Op::Tanh: return unary(i, fmt::format("tanh({})", a), fmt::format("1.0 - {} * {}", t, t));
            case surface::Op::Asinh: return unary(i, fmt::format("asinh({})", a), fmt::format("1.0 / sqrt({} * {} + 1.0)", a, a));
            case surface::Op::Acosh: return unary(i, fmt::format("acosh({})", a), fmt::format("1.0 / sqrt({} * {} - 1.0)", a, a));
            case surface::Op::Atanh: return unary(i, fmt::format("atanh({})", a), fmt::format("1.0 / (1.0 - {} * {})", a, a));
            case surface::Op::Abs: return unary(i, fmt::format("abs({})", a), fmt::format("sign({})", a));
            case surface::Op::Min:
            case surface::Op::Max: {
                const char* f = n.op == surface::Op::Min ? "min" : "max";
                const char* cmp = n.op == surface::Op::Min ? "<" : ">";
                define(i, fmt::format("{}({}, {})", f, a, b));
                if (va || vb) define_gradient(i, fmt::format("({} {} {}) ? {} : {}", a, cmp, b, ga, gb));
                return;
            }
            case surface::Op::Hypot:
                define(i, fmt::format("length(vec2({}, {}))", a, b));
                if (va || vb) define_gradient(i, fmt::format("({} * {} + {} * {}) / {}", a, ga, b, gb, t));
                return;
        }
        throw std::logic_error("emit_glsl_surface: unhandled operation");
    }

    const surface::Program& program_;
    VariableCode variables_;
    std::vector<std::string> value_;     // a temporary's name, a literal, or a variable
    std::vector<std::string> gradient_;  // "" where the gradient is zero
    std::string out_;
};

}  // namespace

std::string glsl_float(double value) {
    float f = static_cast<float>(value);
    if (std::isnan(value)) return "uintBitsToFloat(0x7fc00000u)";
    if (std::isinf(f)) return f > 0 ? "uintBitsToFloat(0x7f800000u)" : "uintBitsToFloat(0xff800000u)";
    std::string s = fmt::format("{:.9g}", std::abs(f));
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return std::signbit(f) ? "(-" + s + ")" : s;
}

std::string emit_glsl_surface(const surface::Expr& x, const surface::Expr& y, const surface::Expr& z, const std::string& function_name) {
    if (!is_glsl_identifier(function_name))
        throw std::invalid_argument("emit_glsl_surface: '" + function_name + "' is not a GLSL identifier");
    const surface::Expr* expressions[] = {&x, &y, &z};
    surface::Program program = compile_program(expressions);
    GlslEmitter e(program, {{"uv.x", "uv.y"}, {"vec2(1.0, 0.0)", "vec2(0.0, 1.0)"}, "vec2"});
    std::string out = fmt::format(
        "// Generated by lancer: a parametric surface S(u, v) and its exact partial derivatives.\n"
        "void {}(vec2 uv, out vec3 P, out vec3 Pu, out vec3 Pv) {{\n",
        function_name);
    out += e.body();
    const auto& o = program.outputs;
    out += fmt::format("    P = vec3({}, {}, {});\n", e.value(o[0]), e.value(o[1]), e.value(o[2]));
    out += fmt::format("    Pu = vec3({}.x, {}.x, {}.x);\n", e.grad(o[0]), e.grad(o[1]), e.grad(o[2]));
    out += fmt::format("    Pv = vec3({}.y, {}.y, {}.y);\n", e.grad(o[0]), e.grad(o[1]), e.grad(o[2]));
    out += "}\n";
    return out;
}

std::string emit_glsl_implicit(const surface::Expr& f, const std::string& function_name, bool in_double_at_a_point) {
    if (!is_glsl_identifier(function_name))
        throw std::invalid_argument("emit_glsl_implicit: '" + function_name + "' is not a GLSL identifier");
    const surface::Expr* expressions[] = {&f};
    surface::Program program = compile_program(expressions);
    const int root = program.outputs[0];
    std::string out = "// Generated by lancer: an implicit surface f(x, y, z), its derivatives and its enclosures.\n";
    {
        GlslEmitter e(program, {{"p.x", "p.y", "p.z"}, {"d.x", "d.y", "d.z"}, "float"});
        out += fmt::format("float {}(vec3 p, vec3 d, out float df) {{\n", function_name);
        out += e.body();
        out += fmt::format("    df = {};\n    return {};\n}}\n", e.grad(root), e.value(root));
    }
    {
        GlslEmitter e(program, {{"p.x", "p.y", "p.z"}, {"vec3(1.0, 0.0, 0.0)", "vec3(0.0, 1.0, 0.0)", "vec3(0.0, 0.0, 1.0)"},
                            "vec3"});
        out += fmt::format("vec3 {}_gradient(vec3 p) {{\n", function_name);
        out += e.body();
        out += fmt::format("    return {};\n}}\n", e.grad(root));
    }
    out += emit_glsl_interval(program, function_name + "_interval");
    if (in_double_at_a_point) out += emit_glsl_interval_at_a_point(program, function_name + "_at_a_point");
    return out;
}

}  // namespace lancer::gpu

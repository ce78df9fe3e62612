#include "gpu/shaders/glsl_interval_emitter.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "core/float_rounding.hpp"
#include "gpu/shaders/glsl_emitter.hpp"

namespace lancer::gpu {
namespace {

constexpr int kMaxChain = 64;  // integer powers up to this are products; beyond, pow() with a wide margin

// x^m (m >= 1) as products, by squaring.
std::string chain(const std::string& x, int m) {
    if (m == 1) return x;
    if (m % 2 == 0) {
        std::string h = chain(x, m / 2);
        return "(" + h + " * " + h + ")";
    }
    return "(" + x + " * " + chain(x, m - 1) + ")";
}

// A double literal that reads back as `value` (the "#" keeps a decimal point: "2lf" is no literal).
std::string glsl_double(double value) { return fmt::format("{:#.17g}lf", value); }

class GlslIntervalEmitter {
public:
    // `at_a_point`: the value alone, in double (interval.glsl's dvec2 overloads).
    GlslIntervalEmitter(const surface::Program& program, bool at_a_point)
        : program_(program), interval_(at_a_point ? "dvec2" : "vec2"),
          value_(program.nodes.size()), derivative_(program.nodes.size()) {}

    std::string run(const std::string& name) {
        out_ = fmt::format("void {}(vec3 o, vec3 d, vec2 s, out vec2 f, out vec2 df) {{\n", name);
        for (std::size_t i = 0; i < program_.nodes.size(); ++i) emit(static_cast<int>(i));
        const int root = program_.outputs[0];
        out_ += fmt::format("    f = {};\n    df = {};\n}}\n", value_[root], der(root));
        return out_;
    }

    std::string run_at_a_point(const std::string& name) {
        out_ = fmt::format("dvec2 {}(dvec3 o, dvec3 d, dvec2 s) {{\n", name);
        for (std::size_t i = 0; i < program_.nodes.size(); ++i) emit_at_a_point(static_cast<int>(i));
        out_ += fmt::format("    return {};\n}}\n", value_[program_.outputs[0]]);
        return out_;
    }

private:
    std::string der(int i) const { return derivative_[i].empty() ? "vec2(0.0)" : derivative_[i]; }
    bool varies(int i) const { return !derivative_[i].empty(); }

    std::string temp(const std::string& prefix, int i, const std::string& code) {
        return temp_of(interval_, prefix, i, code);
    }
    std::string temp_of(const std::string& type, const std::string& prefix, int i, const std::string& code) {
        std::string name = fmt::format("{}{}", prefix, i);
        out_ += fmt::format("    {} {} = {};\n", type, name, code);
        return name;
    }
    void define(int i, const std::string& code) { value_[i] = temp("v", i, code); }
    void define_derivative(int i, const std::string& code) { derivative_[i] = temp("w", i, code); }

    // The interval of a^k for an integer k, as a temporary named after node i and `tag`.
    std::string power(const std::string& a, int k, int i, const std::string& tag) { return power_of(interval_, a, k, i, tag); }
    std::string power_of(const std::string& type, const std::string& a, int k, int i, const std::string& tag) {
        if (k == 0) return type + "(1.0)";
        if (k < 0) return temp_of(type, "r" + tag, i, fmt::format("i_div({}(1.0), {})", type, power_of(type, a, -k, i, tag + "n")));
        if (k == 1) return a;
        if (k == 2) return temp_of(type, "p" + tag, i, fmt::format("i_sqr({})", a));
        std::string base = a;
        if (k % 2 == 0) base = temp_of(type, "m" + tag, i, fmt::format("i_magnitudes({})", a));
        std::string r;
        if (k <= kMaxChain) {
            r = fmt::format("i_widen_n({}({}, {}), {})", type, chain(base + ".x", k), chain(base + ".y", k),
                            glsl_float(2.0 * k));
        } else {
            // Odd powers keep the sign: pow() of the magnitude, the sign put back.
            std::string lo = k % 2 ? fmt::format("sign({0}.x) * pow(abs({0}.x), {1})", base, glsl_float(k))
                                   : fmt::format("pow({}.x, {})", base, glsl_float(k));
            std::string hi = k % 2 ? fmt::format("sign({0}.y) * pow(abs({0}.y), {1})", base, glsl_float(k))
                                   : fmt::format("pow({}.y, {})", base, glsl_float(k));
            r = fmt::format("i_widen_n(vec2({}, {}), {})", lo, hi, glsl_float(100.0 * k));
        }
        if (k % 2 == 0) r = fmt::format("max({}, {}(0.0, -I_INF))", r, type);
        return temp_of(type, "p" + tag, i, r);
    }

    // A function of one argument with derivative k(a) da.
    void unary(int i, const std::string& value, const std::string& k) {
        const surface::Node& n = program_.nodes[i];
        define(i, value);
        if (varies(n.a)) define_derivative(i, fmt::format("i_mul({}, {})", k, derivative_[n.a]));
    }

    void emit(int i) {
        const surface::Node& n = program_.nodes[i];
        const std::string a = n.a >= 0 ? value_[n.a] : "", b = n.b >= 0 ? value_[n.b] : "";
        const std::string da = n.a >= 0 ? der(n.a) : "", db = n.b >= 0 ? der(n.b) : "";
        const bool va = n.a >= 0 && varies(n.a), vb = n.b >= 0 && varies(n.b);
        switch (n.op) {
            case surface::Op::Constant:
                value_[i] = fmt::format("vec2({}, {})", glsl_float(round_down(n.value)), glsl_float(round_up(n.value)));
                return;
            case surface::Op::Variable: {
                const char axis = "xyz"[static_cast<int>(n.value)];
                define(i, fmt::format("i_affine(o.{0}, d.{0}, s)", axis));
                derivative_[i] = fmt::format("vec2(d.{})", axis);
                return;
            }
            case surface::Op::Add:
            case surface::Op::Sub: {
                const char* f = n.op == surface::Op::Add ? "i_add" : "i_sub";
                define(i, fmt::format("{}({}, {})", f, a, b));
                if (va && vb) define_derivative(i, fmt::format("{}({}, {})", f, da, db));
                else if (va) derivative_[i] = da;
                else if (vb) derivative_[i] = n.op == surface::Op::Add ? db : temp("w", i, fmt::format("i_neg({})", db));
                return;
            }
            case surface::Op::Neg:
                define(i, fmt::format("i_neg({})", a));
                if (va) define_derivative(i, fmt::format("i_neg({})", da));
                return;
            case surface::Op::Mul:
                define(i, fmt::format("i_mul({}, {})", a, b));
                if (va && vb) define_derivative(i, fmt::format("i_add(i_mul({}, {}), i_mul({}, {}))", da, b, a, db));
                else if (va) define_derivative(i, fmt::format("i_mul({}, {})", da, b));
                else if (vb) define_derivative(i, fmt::format("i_mul({}, {})", a, db));
                return;
            case surface::Op::Div:
                define(i, fmt::format("i_div({}, {})", a, b));
                if (va && vb) define_derivative(i, fmt::format("i_div(i_sub({}, i_mul({}, {})), {})", da, value_[i], db, b));
                else if (va) define_derivative(i, fmt::format("i_div({}, {})", da, b));
                else if (vb) define_derivative(i, fmt::format("i_neg(i_div(i_mul({}, {}), {}))", value_[i], db, b));
                return;
            case surface::Op::PowInt: {
                const int k = static_cast<int>(n.value);
                if (k == 0) {
                    value_[i] = "vec2(1.0)";
                    return;
                }
                value_[i] = power(a, k, i, "");
                if (value_[i] == a) value_[i] = temp("v", i, a);
                if (va) {
                    std::string p = power(a, k - 1, i, "d");
                    define_derivative(i, fmt::format("i_mul(i_scale({}, {}), {})", p, glsl_float(k), da));
                }
                return;
            }
            case surface::Op::PowConst:
                return unary(i, fmt::format("i_powc({}, {})", a, glsl_float(n.value)),
                             fmt::format("i_scale(i_powc({}, {}), {})", a, glsl_float(n.value - 1.0), glsl_float(n.value)));
            case surface::Op::Pow: {
                define(i, fmt::format("i_powr({}, {})", a, b));
                std::string terms;
                if (vb) terms = fmt::format("i_mul({}, i_log({}))", db, a);
                if (va) {
                    std::string t = fmt::format("i_div(i_mul({}, {}), {})", b, da, a);
                    terms = terms.empty() ? t : fmt::format("i_add({}, {})", terms, t);
                }
                if (!terms.empty()) define_derivative(i, fmt::format("i_mul({}, {})", value_[i], terms));
                return;
            }
            case surface::Op::Sqr: return unary(i, fmt::format("i_sqr({})", a), fmt::format("i_scale({}, 2.0)", a));
            case surface::Op::Sqrt:
                define(i, fmt::format("i_sqrt({})", a));
                if (va) define_derivative(i, fmt::format("i_div(i_scale({}, 0.5), {})", da, value_[i]));
                return;
            case surface::Op::Cbrt:
                define(i, fmt::format("i_cbrt({})", a));
                if (va) define_derivative(i, fmt::format("i_div({}, i_scale(i_sqr({}), 3.0))", da, value_[i]));
                return;
            case surface::Op::Exp:
                define(i, fmt::format("i_exp({})", a));
                if (va) define_derivative(i, fmt::format("i_mul({}, {})", value_[i], da));
                return;
            case surface::Op::Exp2:
                define(i, fmt::format("i_exp2({})", a));
                if (va) define_derivative(i, fmt::format("i_mul(i_scale({}, {}), {})", value_[i], glsl_float(std::log(2.0)), da));
                return;
            case surface::Op::Log: return unary(i, fmt::format("i_log({})", a), fmt::format("i_div(vec2(1.0), {})", a));
            case surface::Op::Log2:
                return unary(i, fmt::format("i_log2({})", a),
                             fmt::format("i_div(vec2(1.0), i_scale({}, {}))", a, glsl_float(std::log(2.0))));
            case surface::Op::Log10:
                return unary(i, fmt::format("i_log10({})", a),
                             fmt::format("i_div(vec2(1.0), i_scale({}, {}))", a, glsl_float(std::log(10.0))));
            case surface::Op::Sin: return unary(i, fmt::format("i_sin({})", a), fmt::format("i_cos({})", a));
            case surface::Op::Cos: return unary(i, fmt::format("i_cos({})", a), fmt::format("i_neg(i_sin({}))", a));
            case surface::Op::Tan:
                define(i, fmt::format("i_tan({})", a));
                if (va) define_derivative(i, fmt::format("i_mul(i_add(vec2(1.0), i_sqr({})), {})", value_[i], da));
                return;
            case surface::Op::Asin:
                return unary(i, fmt::format("i_asin({})", a),
                             fmt::format("i_div(vec2(1.0), i_sqrt(i_sub(vec2(1.0), i_sqr({}))))", a));
            case surface::Op::Acos:
                return unary(i, fmt::format("i_acos({})", a),
                             fmt::format("i_neg(i_div(vec2(1.0), i_sqrt(i_sub(vec2(1.0), i_sqr({})))))", a));
            case surface::Op::Atan:
                return unary(i, fmt::format("i_atan({})", a), fmt::format("i_div(vec2(1.0), i_add(vec2(1.0), i_sqr({})))", a));
            case surface::Op::Atan2: {
                define(i, fmt::format("i_atan2({}, {})", a, b));
                if (!va && !vb) return;
                // (x dy - y dx) / (x^2 + y^2) with y = a, x = b.
                std::string num = va && vb ? fmt::format("i_sub(i_mul({}, {}), i_mul({}, {}))", b, da, a, db)
                                  : va     ? fmt::format("i_mul({}, {})", b, da)
                                           : fmt::format("i_neg(i_mul({}, {}))", a, db);
                define_derivative(i, fmt::format("i_div({}, i_add(i_sqr({}), i_sqr({})))", num, a, b));
                return;
            }
            case surface::Op::Sinh: return unary(i, fmt::format("i_sinh({})", a), fmt::format("i_cosh({})", a));
            case surface::Op::Cosh: return unary(i, fmt::format("i_cosh({})", a), fmt::format("i_sinh({})", a));
            case surface::Op::Tanh:
                define(i, fmt::format("i_tanh({})", a));
                if (va) define_derivative(i, fmt::format("i_mul(i_sub(vec2(1.0), i_sqr({})), {})", value_[i], da));
                return;
            case surface::Op::Asinh:
                return unary(i, fmt::format("i_asinh({})", a),
                             fmt::format("i_div(vec2(1.0), i_sqrt(i_add(i_sqr({}), vec2(1.0))))", a));
            case surface::Op::Acosh:
                return unary(i, fmt::format("i_acosh({})", a),
                             fmt::format("i_div(vec2(1.0), i_sqrt(i_sub(i_sqr({}), vec2(1.0))))", a));
            case surface::Op::Atanh:
                return unary(i, fmt::format("i_atanh({})", a), fmt::format("i_div(vec2(1.0), i_sub(vec2(1.0), i_sqr({})))", a));
            case surface::Op::Abs:
                define(i, fmt::format("i_abs({})", a));
                if (va) define_derivative(i, fmt::format("i_abs_derivative({}, {})", a, da));
                return;
            case surface::Op::Min:
            case surface::Op::Max: {
                const char* f = n.op == surface::Op::Min ? "min" : "max";
                define(i, fmt::format("i_{}({}, {})", f, a, b));
                if (va || vb) define_derivative(i, fmt::format("i_{}_derivative({}, {}, {}, {})", f, a, b, da, db));
                return;
            }
            case surface::Op::Hypot:
                define(i, fmt::format("i_hypot({}, {})", a, b));
                if (va || vb) {
                    std::string num = va && vb ? fmt::format("i_add(i_mul({}, {}), i_mul({}, {}))", a, da, b, db)
                                      : va     ? fmt::format("i_mul({}, {})", a, da)
                                               : fmt::format("i_mul({}, {})", b, db);
                    define_derivative(i, fmt::format("i_div({}, {})", num, value_[i]));
                }
                return;
        }
        throw std::logic_error("emit_glsl_interval: unhandled operation");
    }

    // The value alone, in double where Vulkan's core instructions allow (arithmetic, sqrt,
    // integer powers as products); the library functions are float's, on an interval rounded
    // outward to float and back.
    void emit_at_a_point(int i) {
        const surface::Node& n = program_.nodes[i];
        const std::string a = n.a >= 0 ? value_[n.a] : "", b = n.b >= 0 ? value_[n.b] : "";
        switch (n.op) {
            case surface::Op::Constant: value_[i] = fmt::format("dvec2({})", glsl_double(n.value)); return;
            case surface::Op::Variable: {
                const char axis = "xyz"[static_cast<int>(n.value)];
                return define(i, fmt::format("i_affine(o.{0}, d.{0}, s)", axis));
            }
            case surface::Op::Add: return define(i, fmt::format("i_add({}, {})", a, b));
            case surface::Op::Sub: return define(i, fmt::format("i_sub({}, {})", a, b));
            case surface::Op::Neg: return define(i, fmt::format("i_neg({})", a));
            case surface::Op::Mul: return define(i, fmt::format("i_mul({}, {})", a, b));
            case surface::Op::Div: return define(i, fmt::format("i_div({}, {})", a, b));
            case surface::Op::Sqr: return define(i, fmt::format("i_sqr({})", a));
            case surface::Op::Sqrt: return define(i, fmt::format("i_sqrt({})", a));
            case surface::Op::Abs: return define(i, fmt::format("i_abs({})", a));
            case surface::Op::Min: return define(i, fmt::format("i_min({}, {})", a, b));
            case surface::Op::Max: return define(i, fmt::format("i_max({}, {})", a, b));
            case surface::Op::PowInt:
                if (std::abs(n.value) <= kMaxChain) {
                    value_[i] = power(a, static_cast<int>(n.value), i, "");
                    if (value_[i] == a) value_[i] = temp("v", i, a);
                    return;
                }
                // Beyond products, float's pow() on each bound (power_of), rounded outward.
                return define(i, fmt::format("i_dbl({})", power_of("vec2", temp_of("vec2", "f", i, "i_flt(" + a + ")"),
                                                                    static_cast<int>(n.value), i, "f")));
            default: return define(i, in_float(n, a, b));
        }
    }

    // Node i's value by interval.glsl's float function, for operands given in double.
    std::string in_float(const surface::Node& n, const std::string& a, const std::string& b) {
        const std::string fa = "i_flt(" + a + ")", fb = b.empty() ? "" : "i_flt(" + b + ")";
        switch (n.op) {
            case surface::Op::PowConst: return fmt::format("i_dbl(i_powc({}, {}))", fa, glsl_float(n.value));
            case surface::Op::Pow: return fmt::format("i_dbl(i_powr({}, {}))", fa, fb);
            case surface::Op::Atan2: return fmt::format("i_dbl(i_atan2({}, {}))", fa, fb);
            case surface::Op::Hypot: return fmt::format("i_dbl(i_hypot({}, {}))", fa, fb);
            default: return fmt::format("i_dbl(i_{}({}))", float_function(n.op), fa);
        }
    }

    static const char* float_function(surface::Op op) {
        switch (op) {
            case surface::Op::Cbrt: return "cbrt";
            case surface::Op::Exp: return "exp";
            case surface::Op::Exp2: return "exp2";
            case surface::Op::Log: return "log";
            case surface::Op::Log2: return "log2";
            case surface::Op::Log10: return "log10";
            case surface::Op::Sin: return "sin";
            case surface::Op::Cos: return "cos";
            case surface::Op::Tan: return "tan";
            case surface::Op::Asin: return "asin";
            case surface::Op::Acos: return "acos";
            case surface::Op::Atan: return "atan";
            case surface::Op::Sinh: return "sinh";
            case surface::Op::Cosh: return "cosh";
            case surface::Op::Tanh: return "tanh";
            case surface::Op::Asinh: return "asinh";
            case surface::Op::Acosh: return "acosh";
            case surface::Op::Atanh: return "atanh";
            default: throw std::logic_error("emit_glsl_interval_at_a_point: unhandled operation");
        }
    }

    const surface::Program& program_;
    const std::string interval_;  // the GLSL type of an interval
    std::vector<std::string> value_;       // a temporary's name or a literal
    std::vector<std::string> derivative_;  // "" where the derivative is zero
    std::string out_;
};

}  // namespace

std::string emit_glsl_interval(const surface::Program& program, const std::string& function_name) {
    return GlslIntervalEmitter(program, false).run(function_name);
}

std::string emit_glsl_interval_at_a_point(const surface::Program& program, const std::string& function_name) {
    return GlslIntervalEmitter(program, true).run_at_a_point(function_name);
}

}  // namespace lancer::gpu

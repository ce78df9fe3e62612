#include "surface/expr/functions.hpp"

#include <array>

namespace lancer::surface {
namespace {

// Every function is smooth where it is defined except abs, min and max (kinks) and tan (poles);
// GLSL has a twin of each (cbrt, log10 and hypot are spelled out by the emitter).
constexpr std::array kFunctions{
    FunctionInfo{"sin", 1, Op::Sin, "sine (radians)"},
    FunctionInfo{"cos", 1, Op::Cos, "cosine (radians)"},
    FunctionInfo{"tan", 1, Op::Tan, "tangent (radians)"},
    FunctionInfo{"asin", 1, Op::Asin, "arc sine, x in [-1, 1]"},
    FunctionInfo{"acos", 1, Op::Acos, "arc cosine, x in [-1, 1]"},
    FunctionInfo{"atan", 1, Op::Atan, "arc tangent"},
    FunctionInfo{"atan2", 2, Op::Atan2, "atan2(y, x): the angle of the point (x, y), in [-pi, pi]"},
    FunctionInfo{"sinh", 1, Op::Sinh, "hyperbolic sine"},
    FunctionInfo{"cosh", 1, Op::Cosh, "hyperbolic cosine"},
    FunctionInfo{"tanh", 1, Op::Tanh, "hyperbolic tangent"},
    FunctionInfo{"asinh", 1, Op::Asinh, "inverse hyperbolic sine"},
    FunctionInfo{"acosh", 1, Op::Acosh, "inverse hyperbolic cosine, x >= 1"},
    FunctionInfo{"atanh", 1, Op::Atanh, "inverse hyperbolic tangent, |x| < 1"},
    FunctionInfo{"exp", 1, Op::Exp, "e^x"},
    FunctionInfo{"exp2", 1, Op::Exp2, "2^x"},
    FunctionInfo{"log", 1, Op::Log, "natural logarithm, x > 0"},
    FunctionInfo{"log2", 1, Op::Log2, "base-2 logarithm, x > 0"},
    FunctionInfo{"log10", 1, Op::Log10, "base-10 logarithm, x > 0"},
    FunctionInfo{"sqrt", 1, Op::Sqrt, "square root, x >= 0"},
    FunctionInfo{"cbrt", 1, Op::Cbrt, "cube root (any sign)"},
    FunctionInfo{"sqr", 1, Op::Sqr, "x^2"},
    FunctionInfo{"abs", 1, Op::Abs, "|x|"},
    FunctionInfo{"pow", 2, Op::Pow, "pow(x, y) = x^y"},
    FunctionInfo{"min", 2, Op::Min, "the smaller argument"},
    FunctionInfo{"max", 2, Op::Max, "the larger argument"},
    FunctionInfo{"hypot", 2, Op::Hypot, "hypot(x, y) = sqrt(x^2 + y^2)"},
};

}  // namespace

std::span<const FunctionInfo> function_table() { return kFunctions; }

const FunctionInfo* find_function(std::string_view name) {
    for (const auto& f : kFunctions)
        if (f.name == name) return &f;
    return nullptr;
}

std::string_view function_name(Op op) {
    for (const auto& f : kFunctions)
        if (f.op == op) return f.name;
    return "";
}

}  // namespace lancer::surface

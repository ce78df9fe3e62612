#pragma once
// A parsed expression in its variables (u and v of a parametric surface; x, y and z of an implicit
// one): a flat list of nodes in post-order (every node after its
// operands, the root last), so that evaluation is one loop and the GLSL emitter can print one
// SSA temporary per node. Every node remembers the column of its operator, function name or
// literal in the source text, for error messages.
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace lancer::surface {

enum class Op : std::uint8_t {
    Constant,  // `value`
    Variable,  // variable number `value` (0, 1, 2) in the order of the parser's variable names
    Add,
    Sub,
    Mul,
    Div,
    Neg,
    PowInt,    // a ^ n, n = `value` an integer constant (any sign of a)
    PowConst,  // a ^ c, c = `value` a non-integer constant (a >= 0)
    Pow,       // a ^ b, b varying (a > 0)
    Sqr,
    Sqrt,
    Cbrt,
    Exp,
    Exp2,
    Log,
    Log2,
    Log10,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Atan2,  // atan2(a, b): the angle of the point (b, a)
    Sinh,
    Cosh,
    Tanh,
    Asinh,
    Acosh,
    Atanh,
    Abs,
    Min,
    Max,
    Hypot,
};

struct Node {
    Op op = Op::Constant;
    int a = -1;  // first operand (index of an earlier node), or -1
    int b = -1;  // second operand; for PowInt/PowConst the exponent's own subtree, kept for checks
    double value = 0.0;
    int column = 0;  // 0-based offset into the source text
};

struct Expr {
    std::vector<Node> nodes;  // post-order; nodes.back() is the root

    int root() const { return static_cast<int>(nodes.size()) - 1; }
};

// A mistake in an expression's text, at a 0-based offset into it.
class ExprError : public UserError {
public:
    ExprError(const std::string& message, int column) : UserError(message), column(column) {}
    int column;
};

}  // namespace lancer::surface

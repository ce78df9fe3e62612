#pragma once
// The expression language of parametric surfaces, x(u, v), y(u, v), z(u, v), and of implicit
// surfaces, f(x, y, z) = 0: the same grammar and functions, with the variables the caller names.
//
// Grammar (recursive descent; one function per rule in parser.cpp):
//
//   expression := term (('+' | '-') term)*
//   term       := unary (('*' | '/') unary)*
//   unary      := ('-' | '+') unary | power
//   power      := primary ('^' unary)?          right-associative: 2^3^2 = 2^9;
//                                               binds tighter than unary minus: -u^2 = -(u^2);
//                                               the exponent may carry a sign: 2^-1
//   primary    := number | name | name '(' arguments ')' | '(' expression ')'
//   arguments  := expression (',' expression)*
//   number     := digits ['.' digits] [exponent] | '.' digits [exponent]    (2, 1.5, .5, 1e-3)
//   name       := letter (letter | digit | '_')*                            (case-sensitive)
//
// Names: the variables (u and v, or x, y and z), the constants pi and e, and the caller's named
// constants (a scene's `params = { R = 2, r = 0.5 }`). There is no implicit multiplication: write 2*u.
//
// Functions (the table in functions.cpp; name, arguments):
//   sin 1, cos 1, tan 1, asin 1, acos 1, atan 1, atan2 2 (y, x), sinh 1, cosh 1, tanh 1,
//   asinh 1, acosh 1, atanh 1, exp 1, exp2 1, log 1 (natural), log2 1, log10 1, sqrt 1,
//   cbrt 1, sqr 1, abs 1, pow 2, min 2, max 2, hypot 2.
//
// Powers: x^n with a constant integer n is defined for every x; x^c with any other constant c
// needs x >= 0 (use cbrt for odd roots of negative numbers); x^y with y varying needs x > 0.
//
// Limits, checked before they can hurt: at most 4096 characters and 64 levels of nesting.
// Every error is an ExprError at the 0-based column of the offending token.
#include <map>
#include <span>
#include <string>
#include <string_view>

#include "surface/expr/expr.hpp"

namespace lancer::surface {

inline constexpr int kMaxExpressionLength = 4096;
inline constexpr int kMaxExpressionDepth = 64;

using Constants = std::map<std::string, double, std::less<>>;

// The names of an expression's variables: variable i is the node Op::Variable with value i.
using Variables = std::span<const std::string_view>;
inline constexpr std::string_view kParametricVariables[] = {"u", "v"};
inline constexpr std::string_view kImplicitVariables[] = {"x", "y", "z"};

// Throws ExprError for a mistake in `text`, and UserError when a constant's name is not a
// name, hides a variable, constant or function, or its value is not finite.
Expr parse_expression(std::string_view text, const Constants& constants, Variables variables = kParametricVariables);

// "u and v", "x, y and z": the variables as messages name them.
std::string list_variables(Variables variables);

}  // namespace lancer::surface

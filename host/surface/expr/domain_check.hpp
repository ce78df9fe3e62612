#pragma once
// Rejects expressions that are undefined at every point of their domain (the (u, v) rectangle of a
// parametric surface, the box of an implicit one): a denominator
// that is identically 0 (1/(u-u), 1/0), sqrt of a range that is negative everywhere, log of one
// that is <= 0 everywhere, asin/acos of one outside [-1, 1] everywhere (likewise acosh, atanh and
// powers). An operation that is invalid only somewhere (1/u on [0, 1]) is accepted: the surface
// simply has no points there.
#include <optional>
#include <span>

#include "surface/expr/expr.hpp"
#include "surface/interval.hpp"

namespace lancer::surface {

// Throws ExprError at the column of the first (innermost) offending operator or function.
// The domain is the box of the expression's variables, one interval each; UserError when it is
// not finite or empty.
void check_expression_domain(const Expr& expr, std::span<const Interval> domain);
inline void check_expression_domain(const Expr& expr, Interval u, Interval v) {
    const Interval uv[] = {u, v};
    check_expression_domain(expr, uv);
}

// For an expression whose value is infinite or NaN at every sample point of the domain (1e308*10*u,
// exp(1000) + v, 0*exp(1000)): the error at the operation where that starts, the first whose
// result is never finite although its operands sometimes are. Otherwise nothing. It picks the
// column for a surface that has already been found to be nowhere finite.
std::optional<ExprError> where_non_finite_starts(const Expr& expr, std::span<const Interval> domain);
inline std::optional<ExprError> where_non_finite_starts(const Expr& expr, Interval u, Interval v) {
    const Interval uv[] = {u, v};
    return where_non_finite_starts(expr, uv);
}

}  // namespace lancer::surface

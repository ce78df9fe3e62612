#pragma once
// Rejects expressions that are undefined at every point of their (u, v) domain: a denominator
// that is identically 0 (1/(u-u), 1/0), sqrt of a range that is negative everywhere, log of one
// that is <= 0 everywhere, asin/acos of one outside [-1, 1] everywhere (likewise acosh, atanh and
// powers). An operation that is invalid only somewhere (1/u on [0, 1]) is accepted: the surface
// simply has no points there.
#include <optional>

#include "surface/expr/expr.hpp"
#include "surface/interval.hpp"

namespace lancer::surface {

// Throws ExprError at the column of the first (innermost) offending operator or function.
void check_expression_domain(const Expr& expr, Interval u, Interval v);

// For an expression whose value is infinite or NaN at every sample point of the domain (1e308*10*u,
// exp(1000) + v, 0*exp(1000)): the error at the operation where that starts, the first whose
// result is never finite although its operands sometimes are. Otherwise nothing. It picks the
// column for a surface that has already been found to be nowhere finite.
std::optional<ExprError> where_non_finite_starts(const Expr& expr, Interval u, Interval v);

}  // namespace lancer::surface

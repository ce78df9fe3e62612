#pragma once
// Polynomials in x, y and z with double coefficients: an implicit surface's equation expanded
// symbolically when it is one. The CPU reference substitutes a ray into the expansion to get a
// univariate polynomial in t and takes its real roots from a companion matrix
// (cpu/shapes/polynomial_roots.hpp).
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "surface/expr/expr.hpp"

namespace lancer::surface {

// The highest total degree an implicit surface may have as a polynomial. A polynomial of degree
// n meets a line in at most n points, found as the eigenvalues of an n x n companion matrix; up
// to this degree the expansion has at most C(27, 3) = 2925 terms and the matrix stays small and
// accurate enough for Newton's polish to finish the job.
inline constexpr int kMaxPolynomialDegree = 24;

struct Term {
    int x = 0, y = 0, z = 0;  // exponents
    double coefficient = 0.0;
    int degree() const { return x + y + z; }
};

struct Polynomial3 {
    std::vector<Term> terms;  // non-zero coefficients, each exponent triple once, sorted by (x, y, z)
    int degree() const;       // -1 for the zero polynomial
    double evaluate(const glm::dvec3& p) const;
};

// The expansion of `expr` (an expression in x, y, z: variables 0, 1, 2) when it is a polynomial:
// sums, differences, products, negation, integer powers >= 0, sqr, and division by a non-zero
// constant, of the variables and of constant subexpressions (any function of constants is a
// constant: sin(pi/4)*x). Nothing when it is not (a function of a variable, a variable
// denominator or exponent, a negative or non-integer power of a variable).
// Throws ExprError at the column of the operation whose expansion first exceeds max_degree.
std::optional<Polynomial3> expand_polynomial(const Expr& expr, int max_degree = kMaxPolynomialDegree);

// The coefficients c[0..n] of p(o + s d) = sum c[k] s^k, n = p.degree() (trailing ones may be 0
// for directions along which p has a lower degree).
std::vector<double> restrict_to_line(const Polynomial3& p, const glm::dvec3& o, const glm::dvec3& d);

}  // namespace lancer::surface

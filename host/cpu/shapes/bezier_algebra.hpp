#pragma once
// The algebra behind the CPU reference's ray/Bezier-patch intersection (host/cpu/shapes/bezier.cpp):
// bicubic polynomials in power form, the resultant eigenproblem that eliminates v, and real roots
// of the univariate cubics that give v back (Manocha & Demmel's formulation, as in Kajiya 1982).
#include <array>
#include <vector>

namespace lancer::cpu::bezier_algebra {

// c[k][l] is the coefficient of u^k v^l.
using Bicubic = std::array<std::array<double, 4>, 4>;
using Cubic = std::array<double, 4>;  // coefficient of x^k at [k]

// From Bernstein coefficients b[4*i + j] (of B_i(u) B_j(v)) to power form.
Bicubic bernstein_to_power(const std::array<double, 16>& b);

struct Value {
    double f, fu, fv;
};
Value evaluate(const Bicubic& c, double u, double v);

// f(u, .) as a cubic in v.
Cubic restrict_to_u(const Bicubic& c, double u);

double horner(const Cubic& c, double x);

// Sum of |coefficients|: the scale that residual tests are relative to.
double coefficient_norm(const Bicubic& c);

// The real roots u in [lo, hi] of Res_v(f, g)(u) = 0, as the real finite eigenvalues of the first
// companion linearisation of the Sylvester matrix in v (LAPACK dggev): 18x18 from a 6x6 matrix for
// bicubics, smaller where f and g together have a lower degree in u or v (a degree-elevated patch).
// Coefficients below 1e-10 of the pair's size count as zero in deciding the degree. Eigenvalues
// with |imaginary part| up to 1e-5 count as real: near-double roots at silhouettes come out as
// close complex pairs and the caller's Newton polish decides. Returns false if LAPACK failed.
bool resultant_roots(const Bicubic& f, const Bicubic& g, double lo, double hi, std::vector<double>& roots);

// Real roots of c in [lo, hi], by isolation between its critical points and bisection.
void real_roots(const Cubic& c, double lo, double hi, std::vector<double>& roots);

}  // namespace lancer::cpu::bezier_algebra

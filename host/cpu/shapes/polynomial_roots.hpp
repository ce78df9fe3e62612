#pragma once
// The roots of a univariate polynomial as the eigenvalues of its companion matrix: the CPU
// reference's exact intersection with polynomial implicit surfaces (implicit.cpp). The matrix is
// balanced (LAPACK's dgebal, scaling) before the Hessenberg QR algorithm (dhseqr) finds its
// eigenvalues, which keeps the roots accurate when the coefficients span many magnitudes.
#include <span>
#include <vector>

namespace lancer::cpu {

struct ComplexRoot {
    double re, im;
};

// The roots of c[0] + c[1] s + ... + c[n] s^n, with multiplicity. Leading coefficients below
// 1e-15 of the largest are dropped first (the roots they would add are beyond 1e15 times the
// others); exact zeros at the low end are roots at s = 0. Nothing for a constant.
std::vector<ComplexRoot> polynomial_roots(std::span<const double> c);

}  // namespace lancer::cpu

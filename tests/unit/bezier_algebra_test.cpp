// The resultant eigenproblem behind the CPU reference's ray/patch intersection, on polynomial
// pairs whose common roots are known. The lower-degree pairs are what degree-elevated patches
// (every rational quadric: spheres, tori) give: exact zeros, or rounding noise, where the bicubic
// form has its top coefficients. Built for degree 3 regardless, the Sylvester matrix is singular
// and the eigenvalues are noise; this once lost hits on the torus with some OpenBLAS kernels.
#include <gtest/gtest.h>

#include <initializer_list>

#include "cpu/shapes/bezier_algebra.hpp"

namespace lancer::cpu::bezier_algebra {
namespace {

struct Term {
    int u_power, v_power;
    double coefficient;
};

Bicubic polynomial(std::initializer_list<Term> terms) {
    Bicubic c{};
    for (const Term& t : terms) c[t.u_power][t.v_power] += t.coefficient;
    return c;
}

// Rounding-level values where the bicubic form's top coefficients are zero in exact arithmetic.
Bicubic with_noise_on_top(Bicubic c) {
    double noise = 1.3e-17;
    for (int i = 0; i < 4; ++i) {
        c[3][i] += noise;
        c[i][3] -= noise;
        noise = -0.7 * noise;
    }
    return c;
}

std::vector<double> roots_in_unit_interval(const Bicubic& f, const Bicubic& g) {
    std::vector<double> roots;
    EXPECT_TRUE(resultant_roots(f, g, 0.0, 1.0, roots));
    return roots;
}

void expect_only_root(const std::vector<double>& roots, double expected) {
    ASSERT_EQ(roots.size(), 1u) << (roots.empty() ? 0.0 : roots[0]);
    EXPECT_NEAR(roots[0], expected, 1e-12);
}

// f = u^3 + v^3 - 1/4 and g = u - v meet at u = v = 1/2; the other common roots are complex.
TEST(ResultantRoots, FindTheCommonRootOfABicubicPair) {
    Bicubic f = polynomial({{3, 0, 1.0}, {0, 3, 1.0}, {0, 0, -0.25}});
    Bicubic g = polynomial({{1, 0, 1.0}, {0, 1, -1.0}});
    expect_only_root(roots_in_unit_interval(f, g), 0.5);
}

// f = u^2 + v^2 - 1/2 and g = u - v: degree 2 in both, the common roots are +-1/2.
TEST(ResultantRoots, FindTheRootWhenBothAreQuadraticInEachVariable) {
    Bicubic f = polynomial({{2, 0, 1.0}, {0, 2, 1.0}, {0, 0, -0.5}});
    Bicubic g = polynomial({{1, 0, 1.0}, {0, 1, -1.0}});
    expect_only_root(roots_in_unit_interval(f, g), 0.5);
    expect_only_root(roots_in_unit_interval(with_noise_on_top(f), with_noise_on_top(g)), 0.5);
}

// f = u^3 + v^2 - 3/8 and g = u - v: cubic in u, quadratic in v; u^3 + u^2 - 3/8 has the one
// real root 1/2.
TEST(ResultantRoots, FindTheRootWhenOnlyTheDegreeInVIsLower) {
    Bicubic f = polynomial({{3, 0, 1.0}, {0, 2, 1.0}, {0, 0, -0.375}});
    Bicubic g = polynomial({{1, 0, 1.0}, {0, 1, -1.0}});
    expect_only_root(roots_in_unit_interval(f, g), 0.5);
    expect_only_root(roots_in_unit_interval(with_noise_on_top(f), with_noise_on_top(g)), 0.5);
}

// Two lines: u + v = 1 and u = 3v meet at u = 3/4.
TEST(ResultantRoots, FindTheRootOfTwoLinearPolynomials) {
    Bicubic f = polynomial({{1, 0, 1.0}, {0, 1, 1.0}, {0, 0, -1.0}});
    Bicubic g = polynomial({{1, 0, 1.0}, {0, 1, -3.0}});
    expect_only_root(roots_in_unit_interval(f, g), 0.75);
    expect_only_root(roots_in_unit_interval(with_noise_on_top(f), with_noise_on_top(g)), 0.75);
}

// Neither depends on v: the patch's v-lines run along the ray (or collapse), so the ray can meet it
// only edge-on. No roots, and no failure.
TEST(ResultantRoots, GiveNoRootsWhenNeitherDependsOnV) {
    Bicubic f = polynomial({{1, 0, 1.0}, {0, 0, -0.5}});
    Bicubic g = polynomial({{2, 0, 1.0}, {0, 0, -0.25}});
    EXPECT_TRUE(roots_in_unit_interval(f, g).empty());
}

}  // namespace
}  // namespace lancer::cpu::bezier_algebra

// Implicit surfaces' polynomials: symbolic expansion of expressions in x, y, z (what is and is not
// a polynomial, the true degree after cancellation, the degree limit at its column), the
// restriction to a line, and the companion-matrix roots of univariate polynomials.
#include <algorithm>
#include <cmath>
#include <complex>
#include <random>

#include <gtest/gtest.h>

#include "cpu/shapes/polynomial_roots.hpp"
#include "surface/expr/evaluate.hpp"
#include "surface/expr/parser.hpp"
#include "surface/polynomial.hpp"

namespace lancer {
namespace {

using surface::ExprError;
using surface::Polynomial3;

surface::Expr xyz(const std::string& text, const surface::Constants& constants = {}) {
    return surface::parse_expression(text, constants, surface::kImplicitVariables);
}

std::optional<Polynomial3> expand(const std::string& text, const surface::Constants& constants = {}) {
    return surface::expand_polynomial(xyz(text, constants));
}

double coefficient(const Polynomial3& p, int x, int y, int z) {
    for (const auto& t : p.terms)
        if (t.x == x && t.y == y && t.z == z) return t.coefficient;
    return 0.0;
}

TEST(Polynomial, ExpandsProductsAndPowers) {
    auto p = expand("(x + y)^2 - 3*z");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->degree(), 2);
    EXPECT_EQ(p->terms.size(), 4u);
    EXPECT_EQ(coefficient(*p, 2, 0, 0), 1.0);
    EXPECT_EQ(coefficient(*p, 1, 1, 0), 2.0);
    EXPECT_EQ(coefficient(*p, 0, 2, 0), 1.0);
    EXPECT_EQ(coefficient(*p, 0, 0, 1), -3.0);
}

TEST(Polynomial, TheDegreeIsTheDegreeAfterCancellation) {
    auto p = expand("(x + 1)^2 - x^2");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->degree(), 1);
    EXPECT_EQ(coefficient(*p, 1, 0, 0), 2.0);
    EXPECT_EQ(coefficient(*p, 0, 0, 0), 1.0);
    EXPECT_EQ(expand("x*y*z - z*y*x")->degree(), -1);  // the zero polynomial
}

TEST(Polynomial, ConstantsAndTheirFunctionsAreCoefficients) {
    auto p = expand("sin(pi/2)*x + sqrt(R)*y/2 - exp(0)*z^2 + 2^3", {{"R", 4.0}});
    ASSERT_TRUE(p);
    EXPECT_DOUBLE_EQ(coefficient(*p, 1, 0, 0), 1.0);
    EXPECT_DOUBLE_EQ(coefficient(*p, 0, 1, 0), 1.0);
    EXPECT_DOUBLE_EQ(coefficient(*p, 0, 0, 2), -1.0);
    EXPECT_DOUBLE_EQ(coefficient(*p, 0, 0, 0), 8.0);
    EXPECT_TRUE(expand("sqr(x - 1) + pow(y, 3) + x/4"));
    EXPECT_EQ(expand("x/(y - y + 2)")->degree(), 1);  // the denominator expands to a constant
}

TEST(Polynomial, RecognisesWhatIsNotAPolynomial) {
    for (const char* text : {"sin(x)", "1/x", "x^0.5", "sqrt(x*x)", "abs(x)", "x^y", "2^x", "x^-1", "min(x, y)",
                             "exp(z) - 1"})
        EXPECT_FALSE(expand(text)) << text;
}

TEST(Polynomial, ClassicSurfacesHaveTheirDegrees) {
    EXPECT_EQ(expand("x^2 + y^2 + z^2 - 1")->degree(), 2);
    EXPECT_EQ(expand("(x^2 + y^2 + z^2 + 1 - 0.35^2)^2 - 4*(x^2 + z^2)")->degree(), 4);
    EXPECT_EQ(expand("x^2*y^2 + y^2*z^2 + z^2*x^2 - x*y*z")->degree(), 4);  // Steiner's Roman surface
    const char* barth =
        "4*(p^2*x^2 - y^2)*(p^2*y^2 - z^2)*(p^2*z^2 - x^2) - (1 + 2*p)*(x^2 + y^2 + z^2 - 1)^2";
    EXPECT_EQ(expand(barth, {{"p", (1 + std::sqrt(5.0)) / 2}})->degree(), 6);
}

// The expansion computes the same function as the expression, at random points.
TEST(Polynomial, ExpansionEvaluatesLikeTheExpression) {
    const surface::Constants c{{"p", (1 + std::sqrt(5.0)) / 2}, {"m", 1.3}};
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
    for (const char* text : {"4*(p^2*x^2 - y^2)*(p^2*y^2 - z^2)*(p^2*z^2 - x^2) - (1 + 2*p)*(x^2 + y^2 + z^2 - 1)^2",
                             "(x^2 + y^2 + z^2 - m^2)^2 - (3*m^2 - 1)/(3 - m^2)*(1 - z - sqrt(2)*x)*(1 - z + sqrt(2)*x)*(1 + z + sqrt(2)*y)*(1 + z - sqrt(2)*y)",
                             "(x + 2*y - z/3 + 1)^7 - x*y*z"}) {
        surface::Expr e = xyz(text, c);
        auto p = surface::expand_polynomial(e);
        ASSERT_TRUE(p) << text;
        for (int i = 0; i < 50; ++i) {
            const double point[] = {coordinate(rng), coordinate(rng), coordinate(rng)};
            const double expected = surface::evaluate<double>(e, point);
            EXPECT_NEAR(p->evaluate({point[0], point[1], point[2]}), expected, 1e-11 * (1 + std::abs(expected))) << text;
        }
    }
}

TEST(Polynomial, DegreeAboveTheLimitIsAnErrorAtItsOperation) {
    try {
        expand("y + x^25");
        FAIL() << "no error";
    } catch (const ExprError& e) {
        EXPECT_EQ(e.column, 5);  // the '^'
        EXPECT_NE(std::string(e.what()).find("degree 25"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("24"), std::string::npos) << e.what();
    }
    try {
        expand("(x + y)^13 * (y - z)^12");
        FAIL() << "no error";
    } catch (const ExprError& e) {
        EXPECT_EQ(e.column, 11);  // the '*'
    }
    EXPECT_EQ(expand("(x + y + z + 1)^24")->degree(), 24);
    EXPECT_EQ(expand("(x + y + z + 1)^24")->terms.size(), 2925u);
}

TEST(Polynomial, RestrictionToALineIsTheUnivariatePolynomial) {
    auto p = expand("(x^2 + y^2 + z^2 + 0.8775)^2 - 4*(x^2 + z^2) + x*y*z");
    ASSERT_TRUE(p);
    const glm::dvec3 o(0.3, -2.0, 0.7), d(0.1, 0.9, -0.2);
    std::vector<double> c = surface::restrict_to_line(*p, o, d);
    ASSERT_EQ(c.size(), 5u);
    for (double s : {-3.0, -0.5, 0.0, 0.25, 1.7}) {
        double horner = 0.0;
        for (std::size_t k = c.size(); k-- > 0;) horner = horner * s + c[k];
        double direct = p->evaluate(o + s * d);
        EXPECT_NEAR(horner, direct, 1e-12 * (1 + std::abs(direct))) << s;
    }
}

// Random polynomials built from known roots: real ones in [-1, 1], at least 0.05 apart, and
// complex pairs. The companion matrix gives every real root to near double precision.
TEST(PolynomialRoots, FindsEveryKnownRealRoot) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> count(1, 12);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<double> real;
        std::vector<std::complex<double>> all;
        int n_real = count(rng), n_pairs = count(rng) / 3;
        while (static_cast<int>(real.size()) < n_real) {
            double r = unit(rng);
            if (std::any_of(real.begin(), real.end(), [&](double q) { return std::abs(q - r) < 0.05; })) continue;
            real.push_back(r);
            all.emplace_back(r, 0.0);
        }
        for (int i = 0; i < n_pairs; ++i) {
            std::complex<double> z(unit(rng), 0.05 + std::abs(unit(rng)));
            all.push_back(z);
            all.push_back(std::conj(z));
        }
        std::vector<std::complex<double>> c{std::complex<double>(3.0 * (1.0 + std::abs(unit(rng))))};
        for (const auto& z : all) {  // multiply by (s - z)
            std::vector<std::complex<double>> next(c.size() + 1);
            for (std::size_t k = 0; k < c.size(); ++k) {
                next[k + 1] += c[k];
                next[k] -= z * c[k];
            }
            c = next;
        }
        std::vector<double> coefficients;
        for (const auto& z : c) coefficients.push_back(z.real());
        std::vector<cpu::ComplexRoot> roots = cpu::polynomial_roots(coefficients);
        ASSERT_EQ(roots.size(), all.size()) << trial;
        for (double r : real) {
            double best = 1e9;
            for (const auto& z : roots) best = std::min(best, std::abs(std::complex<double>(z.re, z.im) - r));
            EXPECT_LT(best, 1e-9) << "trial " << trial << " root " << r;
        }
    }
}

TEST(PolynomialRoots, DropsNegligibleLeadingCoefficientsAndKeepsRootsAtZero) {
    // 1e-20 s^3 + s^2 - 1 = 0 on [-1, 1]: roots -1 and 1 (the third is near -1e20, dropped).
    auto roots = cpu::polynomial_roots(std::vector<double>{-1.0, 0.0, 1.0, 1e-20});
    ASSERT_EQ(roots.size(), 2u);
    std::vector<double> re{roots[0].re, roots[1].re};
    std::sort(re.begin(), re.end());
    EXPECT_NEAR(re[0], -1.0, 1e-15);
    EXPECT_NEAR(re[1], 1.0, 1e-15);
    // s^2 (s - 0.5): two roots exactly 0.
    roots = cpu::polynomial_roots(std::vector<double>{0.0, 0.0, -0.5, 1.0});
    ASSERT_EQ(roots.size(), 3u);
    EXPECT_EQ(roots[0].re, 0.0);
    EXPECT_EQ(roots[1].re, 0.0);
    EXPECT_NEAR(roots[2].re, 0.5, 1e-15);
    EXPECT_TRUE(cpu::polynomial_roots(std::vector<double>{2.0}).empty());
}

}  // namespace
}  // namespace lancer

// Evaluating expressions: values worked out by hand, derivatives (Dual<double>) against central
// differences on the classic surfaces, bounds (Interval, Dual<Interval>) that contain sampled
// values and derivatives, and compiled programs that compute bit for bit what evaluate() does.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "surface/expr/evaluate.hpp"
#include "surface/expr/parser.hpp"
#include "surface/expr/program.hpp"
#include "unit/surface_fixtures.hpp"

namespace lancer::surface {
namespace {

using std::numbers::pi;

TEST(ExprEvaluate, HandComputedValues) {
    Constants p{{"R", 1.0}, {"r", 0.35}};
    Expr x = parse_expression("(R + r*cos(v))*cos(u)", p);
    Expr z = parse_expression("r*sin(v)", p);
    EXPECT_DOUBLE_EQ(evaluate(x, 0.0, 0.0), 1.35);
    EXPECT_DOUBLE_EQ(evaluate(x, pi, 0.0), -1.35);
    EXPECT_NEAR(evaluate(x, 0.0, pi / 2), 1.0, 1e-15);
    EXPECT_DOUBLE_EQ(evaluate(z, 0.0, pi / 2), 0.35);
    Expr enneper = parse_expression("u - u^3/3 + u*v^2", {});
    EXPECT_DOUBLE_EQ(evaluate(enneper, 3.0, 2.0), 3.0 - 9.0 + 12.0);
    Expr mixed = parse_expression("hypot(u, v) * exp(-u) + atan2(v, u) / pi", {});
    EXPECT_DOUBLE_EQ(evaluate(mixed, 3.0, 4.0), 5.0 * std::exp(-3.0) + std::atan2(4.0, 3.0) / pi);
}

TEST(ExprEvaluate, DualGivesHandComputedDerivatives) {
    Expr e = parse_expression("u^2 * sin(v)", {});
    Dual<double> d = evaluate(e, Dual<double>::variable_u(3.0), Dual<double>::variable_v(0.5));
    EXPECT_DOUBLE_EQ(d.v, 9.0 * std::sin(0.5));
    EXPECT_DOUBLE_EQ(d.du, 6.0 * std::sin(0.5));
    EXPECT_DOUBLE_EQ(d.dv, 9.0 * std::cos(0.5));
}

// Every function's derivative rule, by central differences at a point inside its domain.
TEST(ExprEvaluate, DualMatchesFiniteDifferencesForEveryFunction) {
    const char* texts[] = {
        "sin(u*v)",     "cos(u+v)",       "tan(0.3*u)",      "asin(0.4*u)",    "acos(0.3*v)",   "atan(u*v)",
        "atan2(v, u)",  "sinh(u)",        "cosh(v)",         "tanh(u*v)",      "asinh(u)",      "acosh(1.5+v)",
        "atanh(0.4*u)", "exp(u-v)",       "exp2(u)",         "log(u+v)",       "log2(u*v)",     "log10(u)",
        "sqrt(u*v)",    "cbrt(u-2*v)",    "sqr(u-v)",        "abs(u-2*v)",     "pow(u, v)",     "u^v",
        "min(u, v^2)",  "max(u, v^2)",    "hypot(u, v)",     "u^3",            "u^-2",          "v^2.5",
        "u/(v+1)",      "-u*v",           "(u-v)*(u+v)",     "2^u",            "u^(1/3)",       "e^v"};
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0.6, 1.4);
    for (const char* text : texts) {
        Expr e = parse_expression(text, {});
        for (int i = 0; i < 20; ++i) {
            double u = unit(rng), v = unit(rng) * 0.7;
            Dual<double> d = evaluate(e, Dual<double>::variable_u(u), Dual<double>::variable_v(v));
            const double h = 1e-6;
            double fu = (evaluate(e, u + h, v) - evaluate(e, u - h, v)) / (2 * h);
            double fv = (evaluate(e, u, v + h) - evaluate(e, u, v - h)) / (2 * h);
            EXPECT_NEAR(d.v, evaluate(e, u, v), 1e-15 * (1 + std::abs(d.v))) << text;
            EXPECT_NEAR(d.du, fu, 1e-6 * (1 + std::abs(fu))) << text << " at " << u << ", " << v;
            EXPECT_NEAR(d.dv, fv, 1e-6 * (1 + std::abs(fv))) << text << " at " << u << ", " << v;
        }
    }
}

TEST(ExprEvaluate, DualMatchesFiniteDifferencesOnClassicSurfaces) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& spec : test::classic_surfaces()) {
        ParametricSurface s = test::make_surface(spec);
        const Expr* xyz[] = {&s.x, &s.y, &s.z};
        for (int i = 0; i < 200; ++i) {
            double u = spec.u0 + (spec.u1 - spec.u0) * (0.01 + 0.98 * unit(rng));
            double v = spec.v0 + (spec.v1 - spec.v0) * (0.01 + 0.98 * unit(rng));
            const double hu = 1e-6 * (spec.u1 - spec.u0), hv = 1e-6 * (spec.v1 - spec.v0);
            for (const Expr* e : xyz) {
                Dual<double> d = evaluate(*e, Dual<double>::variable_u(u), Dual<double>::variable_v(v));
                double fu = (evaluate(*e, u + hu, v) - evaluate(*e, u - hu, v)) / (2 * hu);
                double fv = (evaluate(*e, u, v + hv) - evaluate(*e, u, v - hv)) / (2 * hv);
                EXPECT_NEAR(d.du, fu, 1e-6 * (1 + std::abs(fu))) << spec.name << " at " << u << ", " << v;
                EXPECT_NEAR(d.dv, fv, 1e-6 * (1 + std::abs(fv))) << spec.name << " at " << u << ", " << v;
            }
        }
    }
}

// Interval and Dual<Interval> evaluation over random sub-boxes contain the double values and
// derivatives at points of the box.
TEST(ExprEvaluate, BoundsContainSampledValuesAndDerivatives) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto check = [&](const Expr& e, const std::string& what, double u0, double u1, double v0, double v1) {
        for (int trial = 0; trial < 200; ++trial) {
            double wu = (u1 - u0) * std::pow(10.0, -4.0 * unit(rng)), wv = (v1 - v0) * std::pow(10.0, -4.0 * unit(rng));
            double ul = u0 + (u1 - u0 - wu) * unit(rng), vl = v0 + (v1 - v0 - wv) * unit(rng);
            Interval U(ul, ul + wu), V(vl, vl + wv);
            Interval bound = evaluate(e, U, V);
            Dual<Interval> dual = evaluate(e, Dual<Interval>::variable_u(U), Dual<Interval>::variable_v(V));
            for (int k = 0; k < 30; ++k) {
                double u = k == 0 ? U.lo : (k == 1 ? U.hi : U.lo + wu * unit(rng));
                double v = k == 0 ? V.lo : (k == 1 ? V.hi : V.lo + wv * unit(rng));
                u = std::clamp(u, U.lo, U.hi);
                v = std::clamp(v, V.lo, V.hi);
                double value = evaluate(e, u, v);
                Dual<double> d = evaluate(e, Dual<double>::variable_u(u), Dual<double>::variable_v(v));
                if (std::isnan(value)) continue;
                ASSERT_TRUE(bound.contains(value)) << what << " at " << u << ", " << v;
                ASSERT_TRUE(dual.v.contains(value)) << what;
                if (std::isfinite(d.du)) {
                    ASSERT_TRUE(dual.du.contains(d.du)) << what << " du at " << u << ", " << v;
                }
                if (std::isfinite(d.dv)) {
                    ASSERT_TRUE(dual.dv.contains(d.dv)) << what << " dv at " << u << ", " << v;
                }
            }
        }
    };
    for (const auto& spec : test::classic_surfaces()) {
        ParametricSurface s = test::make_surface(spec);
        check(s.x, spec.name + ".x", spec.u0, spec.u1, spec.v0, spec.v1);
        check(s.y, spec.name + ".y", spec.u0, spec.u1, spec.v0, spec.v1);
        check(s.z, spec.name + ".z", spec.u0, spec.u1, spec.v0, spec.v1);
    }
    for (const char* text : {"1/(u - 0.5)", "sqrt(u - 0.3) + log(v)", "abs(u - v) + min(u, v) * max(u, 2*v)",
                             "atan2(v - 0.5, u - 0.5)", "tan(3*u)", "u^v + v^-3", "asin(2*u - 1) * acos(v)",
                             "hypot(u - 0.5, v - 0.5)", "cbrt(u - 0.5)"}) {
        check(parse_expression(text, {}), text, 0.01, 1.0, 0.01, 1.0);
    }
}

TEST(ExprEvaluate, ProgramsComputeExactlyWhatEvaluateDoes) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& spec : test::classic_surfaces()) {
        ParametricSurface s = test::make_surface(spec);
        const Expr* xyz[] = {&s.x, &s.y, &s.z};
        Program program = compile_program(xyz);
        ASSERT_EQ(program.outputs.size(), 3u);
        EXPECT_LT(program.nodes.size(), s.x.nodes.size() + s.y.nodes.size() + s.z.nodes.size()) << spec.name;
        for (int i = 0; i < 100; ++i) {
            double u = spec.u0 + (spec.u1 - spec.u0) * unit(rng), v = spec.v0 + (spec.v1 - spec.v0) * unit(rng);
            double p[3];
            evaluate_program(program, u, v, p);
            Dual<double> d[3];
            evaluate_program(program, Dual<double>::variable_u(u), Dual<double>::variable_v(v), d);
            for (int k = 0; k < 3; ++k) {
                EXPECT_EQ(p[k], evaluate(*xyz[k], u, v)) << spec.name;
                Dual<double> e = evaluate(*xyz[k], Dual<double>::variable_u(u), Dual<double>::variable_v(v));
                EXPECT_EQ(d[k].du, e.du) << spec.name;
                EXPECT_EQ(d[k].dv, e.dv) << spec.name;
            }
        }
    }
}

TEST(ExprEvaluate, ProgramsShareSubexpressionsAndFoldConstants) {
    Constants p{{"R", 1.0}, {"r", 0.35}};
    Expr x = parse_expression("(R + r*cos(v))*cos(u)", p);
    Expr y = parse_expression("(R + r*cos(v))*sin(u)", p);
    Expr z = parse_expression("2*pi*r*sin(v)", p);
    const Expr* xyz[] = {&x, &y, &z};
    Program program = compile_program(xyz);
    int cos_v = 0, constants = 0;
    for (const Node& n : program.nodes) {
        if (n.op == Op::Cos && program.nodes[n.a].op == Op::Variable && program.nodes[n.a].value == 1.0) ++cos_v;
        if (n.op == Op::Constant) ++constants;
    }
    EXPECT_EQ(cos_v, 1);      // cos(v) computed once for x and y
    EXPECT_EQ(constants, 3);  // R, r, and 2*pi*r folded into one
}

}  // namespace
}  // namespace lancer::surface

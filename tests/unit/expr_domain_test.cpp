// check_expression_domain: an expression that is undefined at every point of its domain is
// rejected at the column of the operation at fault; one that is undefined only somewhere is not.
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "surface/expr/domain_check.hpp"
#include "surface/expr/parser.hpp"

namespace lancer::surface {
namespace {

const Interval kUnit(0.0, 1.0);

void expect_rejected(const std::string& text, int column, const std::string& fragment, Interval u = kUnit,
                     Interval v = kUnit) {
    Expr e = parse_expression(text, {});
    try {
        check_expression_domain(e, u, v);
        ADD_FAILURE() << "accepted: " << text;
    } catch (const ExprError& error) {
        EXPECT_EQ(error.column, column) << text << ": " << error.what();
        EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << text << ": " << error.what();
    }
}

void expect_accepted(const std::string& text, Interval u = kUnit, Interval v = kUnit) {
    EXPECT_NO_THROW(check_expression_domain(parse_expression(text, {}), u, v)) << text;
}

TEST(ExprDomain, DivisionByZeroEverywhereIsRejectedAtTheSlash) {
    expect_rejected("1/(u-u)", 1, "division by zero");
    expect_rejected("1/0", 1, "division by zero");
    expect_rejected("u + v/(0*u)", 5, "division by zero");
    expect_rejected("(u-u)^-2", 5, "division by zero");
}

TEST(ExprDomain, DivisionByZeroSomewhereIsAccepted) {
    expect_accepted("1/u");
    expect_accepted("u/(v - 0.5)");
    expect_accepted("1/sin(u)", Interval(0.0, 2 * std::numbers::pi));
}

TEST(ExprDomain, SqrtLogAsinAcosOutsideTheirDomainEverywhere) {
    expect_rejected("sqrt(-1 - u^2)", 0, "sqrt of a negative number");
    expect_rejected("u + sqrt(u - 2)", 4, "sqrt of a negative number");
    expect_rejected("log(-u)", 0, "log of a number <= 0");
    expect_rejected("2*log10(u - u)", 2, "log10 of a number <= 0");
    expect_rejected("asin(2 + u)", 0, "asin of a number outside [-1, 1]");
    expect_rejected("acos(-1.5 - v)", 0, "acos of a number outside [-1, 1]");
    expect_rejected("acosh(u - 1)", 0, "acosh");
    expect_rejected("atanh(1 + u)", 0, "atanh");
    expect_rejected("(u - 2)^0.5", 7, "non-integer");
    expect_rejected("sqrt(u - u - 1)", 0, "sqrt");  // intervals see [-2, 0]; sub-boxes prove it
}

TEST(ExprDomain, PartlyValidIsAccepted) {
    expect_accepted("sqrt(u - 0.5)");
    expect_accepted("sqrt(u - 2)", Interval(0.0, 3.0));
    expect_accepted("log(u)");
    expect_accepted("asin(2*u)");
    expect_accepted("acos(u)");
    expect_accepted("u^0.5");
    expect_accepted("u^v");
    expect_accepted("sqrt(1e-9 - (u - 0.1234)^2)");  // valid only on a sliver: no proof, no rejection
}

TEST(ExprDomain, TheInnermostCulpritIsReported) {
    expect_rejected("sqrt(log(-1 - u^2))", 5, "log");
    expect_rejected("u + sqrt(v) * log(-1 - v^2)", 14, "log");
}

TEST(ExprDomain, ADomainThatIsNotFiniteIsAUserError) {
    EXPECT_THROW(check_expression_domain(parse_expression("u", {}), Interval(0.0, kInf), kUnit), UserError);
    EXPECT_THROW(check_expression_domain(parse_expression("u", {}), Interval::empty(), kUnit), UserError);
}

}  // namespace
}  // namespace lancer::surface

// The expression language: precedence, associativity, numbers, names, functions, and every
// error with the column it points at.
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "surface/expr/domain_check.hpp"
#include "surface/expr/evaluate.hpp"
#include "gpu/shaders/glsl_emitter.hpp"
#include "surface/expr/functions.hpp"
#include "surface/expr/parser.hpp"

namespace lancer::surface {
namespace {

const Constants kParams{{"R", 2.0}, {"r", 0.5}};

double eval(const std::string& text, double u = 0.0, double v = 0.0, const Constants& params = kParams) {
    return evaluate(parse_expression(text, params), u, v);
}

// The error parse_expression throws for `text` (fails the test when it does not throw).
ExprError error_of(const std::string& text, const Constants& params = kParams) {
    try {
        parse_expression(text, params);
    } catch (const ExprError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for: " << text;
    return ExprError("", -1);
}

#define EXPECT_EXPR_ERROR(text, column_, fragment)                                       \
    do {                                                                                 \
        ExprError e_ = error_of(text);                                                   \
        EXPECT_EQ(e_.column, column_) << (text) << ": " << e_.what();                    \
        EXPECT_NE(std::string(e_.what()).find(fragment), std::string::npos)              \
            << (text) << ": '" << e_.what() << "' lacks '" << (fragment) << "'";         \
    } while (0)

TEST(ExprParser, Precedence) {
    EXPECT_EQ(eval("1 + 2 * 3"), 7.0);
    EXPECT_EQ(eval("(1 + 2) * 3"), 9.0);
    EXPECT_EQ(eval("2 * 3 ^ 2"), 18.0);
    EXPECT_EQ(eval("1 + 6 / 2 * 3"), 10.0);
    EXPECT_EQ(eval("2 * u + v", 3.0, 4.0), 10.0);
}

TEST(ExprParser, Associativity) {
    EXPECT_EQ(eval("8 - 4 - 2"), 2.0);
    EXPECT_EQ(eval("8 / 4 / 2"), 1.0);
    EXPECT_EQ(eval("2 ^ 3 ^ 2"), 512.0);  // right-associative: 2^(3^2)
    EXPECT_EQ(eval("2 ^ -2 ^ 2"), 0.0625);  // 2^(-(2^2))
}

TEST(ExprParser, UnaryMinus) {
    EXPECT_EQ(eval("-u^2", 3.0), -9.0);  // ^ binds tighter than unary minus
    EXPECT_EQ(eval("-2^2"), -4.0);
    EXPECT_EQ(eval("(-2)^2"), 4.0);
    EXPECT_EQ(eval("2^-1"), 0.5);
    EXPECT_EQ(eval("2 * -3"), -6.0);
    EXPECT_EQ(eval("1 - -1"), 2.0);
    EXPECT_EQ(eval("--2"), 2.0);
    EXPECT_EQ(eval("+u", 5.0), 5.0);
    EXPECT_EQ(eval("-u * v", 2.0, 3.0), -6.0);
}

TEST(ExprParser, Numbers) {
    EXPECT_EQ(eval("2"), 2.0);
    EXPECT_EQ(eval("1.5"), 1.5);
    EXPECT_EQ(eval(".5"), 0.5);
    EXPECT_EQ(eval("3."), 3.0);
    EXPECT_EQ(eval("1e-3"), 1e-3);
    EXPECT_EQ(eval("2.5E+2"), 250.0);
    EXPECT_EQ(eval(" \t1\n+\r2 "), 3.0);
}

TEST(ExprParser, VariablesConstantsAndParams) {
    EXPECT_EQ(eval("u", 1.25, 7.0), 1.25);
    EXPECT_EQ(eval("v", 1.25, 7.0), 7.0);
    EXPECT_EQ(eval("pi"), std::numbers::pi);
    EXPECT_EQ(eval("e"), std::numbers::e);
    EXPECT_EQ(eval("R"), 2.0);  // names are case-sensitive
    EXPECT_EQ(eval("r"), 0.5);
    EXPECT_EQ(eval("(R + r*cos(v))*cos(u)", 0.0, 0.0), 2.5);
}

TEST(ExprParser, Functions) {
    const double pi = std::numbers::pi;
    EXPECT_DOUBLE_EQ(eval("sin(pi/2)"), 1.0);
    EXPECT_DOUBLE_EQ(eval("cos(pi)"), -1.0);
    EXPECT_DOUBLE_EQ(eval("tan(pi/4)"), 1.0);
    EXPECT_DOUBLE_EQ(eval("asin(1)"), pi / 2);
    EXPECT_DOUBLE_EQ(eval("acos(-1)"), pi);
    EXPECT_DOUBLE_EQ(eval("atan(1)"), pi / 4);
    EXPECT_DOUBLE_EQ(eval("atan2(1, -1)"), 3 * pi / 4);
    EXPECT_DOUBLE_EQ(eval("sinh(1)"), std::sinh(1.0));
    EXPECT_DOUBLE_EQ(eval("cosh(1)"), std::cosh(1.0));
    EXPECT_DOUBLE_EQ(eval("tanh(1)"), std::tanh(1.0));
    EXPECT_DOUBLE_EQ(eval("asinh(1)"), std::asinh(1.0));
    EXPECT_DOUBLE_EQ(eval("acosh(2)"), std::acosh(2.0));
    EXPECT_DOUBLE_EQ(eval("atanh(0.5)"), std::atanh(0.5));
    EXPECT_DOUBLE_EQ(eval("exp(1)"), std::numbers::e);
    EXPECT_DOUBLE_EQ(eval("exp2(10)"), 1024.0);
    EXPECT_DOUBLE_EQ(eval("log(e^2)"), 2.0);
    EXPECT_DOUBLE_EQ(eval("log2(8)"), 3.0);
    EXPECT_DOUBLE_EQ(eval("log10(1000)"), 3.0);
    EXPECT_DOUBLE_EQ(eval("sqrt(16)"), 4.0);
    EXPECT_DOUBLE_EQ(eval("cbrt(-8)"), -2.0);
    EXPECT_DOUBLE_EQ(eval("sqr(-3)"), 9.0);
    EXPECT_DOUBLE_EQ(eval("abs(-2.5)"), 2.5);
    EXPECT_DOUBLE_EQ(eval("pow(2, 10)"), 1024.0);
    EXPECT_DOUBLE_EQ(eval("min(2, -3)"), -3.0);
    EXPECT_DOUBLE_EQ(eval("max(2, -3)"), 2.0);
    EXPECT_DOUBLE_EQ(eval("hypot(3, 4)"), 5.0);
    EXPECT_DOUBLE_EQ(eval("sin(cos(0))"), std::sin(1.0));
}

TEST(ExprParser, EveryFunctionInTheTableParses) {
    for (const auto& f : function_table()) {
        std::string call = std::string(f.name) + (f.arity == 1 ? "(0.5)" : "(0.5, 0.25)");
        EXPECT_NO_THROW(parse_expression(call, {})) << call;
    }
}

TEST(ExprParser, PowersOfNegativeBases) {
    EXPECT_EQ(eval("u^3", -2.0), -8.0);       // integer exponent: any base
    EXPECT_EQ(eval("u^(1+1)", -3.0), 9.0);    // a constant integer expression counts too
    EXPECT_EQ(eval("pow(u, -1)", -4.0), -0.25);
    EXPECT_TRUE(std::isnan(eval("u^0.5", -1.0)));   // non-integer: needs u >= 0, as in GLSL
    EXPECT_TRUE(std::isnan(eval("u^v", -1.0, 2.0)));  // varying exponent: needs u > 0
    EXPECT_DOUBLE_EQ(eval("u^v", 2.0, 3.0), 8.0);
    EXPECT_DOUBLE_EQ(eval("u^0.5", 2.25), 1.5);
}

TEST(ExprParser, NodesRememberTheirColumns) {
    Expr e = parse_expression("u + sin(v)", {});
    ASSERT_EQ(e.nodes.size(), 4u);
    EXPECT_EQ(e.nodes[0].column, 0);  // u
    EXPECT_EQ(e.nodes[1].column, 8);  // v
    EXPECT_EQ(e.nodes[2].column, 4);  // sin
    EXPECT_EQ(e.nodes[3].column, 2);  // +
    EXPECT_EQ(e.nodes.back().op, Op::Add);
}

TEST(ExprParserErrors, EmptyExpression) {
    EXPECT_EXPR_ERROR("", 0, "empty expression");
    EXPECT_EXPR_ERROR("   ", 0, "empty expression");
}

TEST(ExprParserErrors, UnknownFunctionSuggestsTheClosest) {
    EXPECT_EXPR_ERROR("son(u)", 0, "unknown function 'son' (did you mean 'sin'?)");
    EXPECT_EXPR_ERROR("u + cso(v)", 4, "did you mean 'cos'?");
    EXPECT_EXPR_ERROR("frobnicate(u)", 0, "unknown function 'frobnicate'");
}

TEST(ExprParserErrors, UnknownVariableListsTheNames) {
    EXPECT_EXPR_ERROR("2*w", 2, "unknown variable 'w' (the variables are u and v; constants: pi, e, R, r)");
    EXPECT_EXPR_ERROR("u + pii", 4, "unknown variable 'pii' (did you mean 'pi'?)");
    EXPECT_EXPR_ERROR("sin", 0, "'sin' is a function: write sin(...)");
    EXPECT_EXPR_ERROR("u(2)", 0, "'u' is a variable, not a function");
    EXPECT_EXPR_ERROR("1 + R(2)", 4, "'R' is a constant, not a function");
}

TEST(ExprParserErrors, WrongNumberOfArguments) {
    EXPECT_EXPR_ERROR("sin(u, v)", 0, "sin takes 1 argument, not 2");
    EXPECT_EXPR_ERROR("u*atan2(u)", 2, "atan2 takes 2 arguments, not 1");
    EXPECT_EXPR_ERROR("cos()", 0, "cos takes 1 argument, not 0");
}

TEST(ExprParserErrors, UnexpectedCharacter) {
    EXPECT_EXPR_ERROR("u $ v", 2, "unexpected character '$'");
    EXPECT_EXPR_ERROR("u ** v", 3, "not '*'");
    EXPECT_EXPR_ERROR("u;", 1, "unexpected character ';'");
    EXPECT_EXPR_ERROR("u\x01", 1, "byte 0x01");
}

TEST(ExprParserErrors, MissingParenthesis) {
    EXPECT_EXPR_ERROR("(u + v", 6, "missing ')'");
    EXPECT_EXPR_ERROR("sin(u", 5, "missing ')'");
    EXPECT_EXPR_ERROR("(u v)", 3, "missing ')' before 'v'");
    EXPECT_EXPR_ERROR("u)", 1, "unmatched ')'");
}

TEST(ExprParserErrors, IncompleteAndTrailingInput) {
    EXPECT_EXPR_ERROR("u +", 3, "incomplete expression");
    EXPECT_EXPR_ERROR("u v", 2, "unexpected 'v' after a complete expression");
    EXPECT_EXPR_ERROR("2u", 1, "unexpected 'u' after a complete expression");
    EXPECT_EXPR_ERROR("u * (", 5, "incomplete expression");
    EXPECT_EXPR_ERROR("sin(u,)", 6, "not ')'");
}

TEST(ExprParserErrors, MalformedNumbers) {
    EXPECT_EXPR_ERROR("u + 1e", 4, "malformed number '1e'");
    EXPECT_EXPR_ERROR(".", 0, "malformed number");
    EXPECT_EXPR_ERROR("1e999", 0, "out of range");
}

TEST(ExprParserErrors, NestingDepthIsLimitedBeforeTheStackSuffers) {
    auto nested = [](int n) { return std::string(n, '(') + "u" + std::string(n, ')'); };
    EXPECT_NO_THROW(parse_expression(nested(kMaxExpressionDepth), {}));
    EXPECT_EXPR_ERROR(nested(kMaxExpressionDepth + 1), kMaxExpressionDepth + 1, "nested too deeply");
    // Deep enough to overflow the stack if nesting were not checked as it happens.
    EXPECT_EXPR_ERROR(std::string(4000, '('), kMaxExpressionDepth + 1, "nested too deeply");
    EXPECT_EXPR_ERROR(std::string(4000, '-') + "u", kMaxExpressionDepth + 1, "nested too deeply");
    std::string calls;
    for (int i = 0; i < 100; ++i) calls += "sin(";
    EXPECT_EXPR_ERROR(calls, 4 * (kMaxExpressionDepth + 1), "nested too deeply");
}

TEST(ExprParserErrors, LengthIsLimited) {
    std::string ok = "u";
    while (ok.size() + 2 <= static_cast<std::size_t>(kMaxExpressionLength)) ok += "+u";
    EXPECT_NO_THROW(parse_expression(ok, {}));
    EXPECT_EXPR_ERROR(std::string(kMaxExpressionLength + 1, ' '), kMaxExpressionLength, "too long");
}

TEST(ExprParserErrors, BadParamsAreUserErrors) {
    EXPECT_THROW(parse_expression("u", {{"u", 1.0}}), UserError);
    EXPECT_THROW(parse_expression("u", {{"pi", 3.0}}), UserError);
    EXPECT_THROW(parse_expression("u", {{"sin", 1.0}}), UserError);
    EXPECT_THROW(parse_expression("u", {{"a b", 1.0}}), UserError);
    EXPECT_THROW(parse_expression("u", {{"k", std::nan("")}}), UserError);
    try {
        parse_expression("u", {{"v", 1.0}});
    } catch (const ExprError&) {
        FAIL() << "a bad parameter is not a mistake in the expression's text";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("would hide the variable v"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lancer::surface

namespace lancer::surface {
namespace {

// A random well-formed expression (for fuzzing).
std::string random_expression(std::mt19937& rng, int depth) {
    std::uniform_int_distribution<int> choice(0, depth > 0 ? 7 : 2);
    const char* leaves[] = {"u", "v", "pi", "e", "R", "2", "0.5", "1e-3", "3"};
    switch (choice(rng)) {
        case 0:
        case 1:
        case 2: return leaves[std::uniform_int_distribution<int>(0, 8)(rng)];
        case 3: return "-" + random_expression(rng, depth - 1);
        case 4: return "(" + random_expression(rng, depth - 1) + ")";
        case 5: {
            const char* ops[] = {" + ", " - ", " * ", " / ", "^"};
            return random_expression(rng, depth - 1) + ops[std::uniform_int_distribution<int>(0, 4)(rng)] +
                   random_expression(rng, depth - 1);
        }
        default: {
            auto table = function_table();
            const auto& f = table[std::uniform_int_distribution<std::size_t>(0, table.size() - 1)(rng)];
            std::string call = std::string(f.name) + "(" + random_expression(rng, depth - 1);
            for (int i = 1; i < f.arity; ++i) call += ", " + random_expression(rng, depth - 1);
            return call + ")";
        }
    }
}

// Every well-formed expression parses; damaged ones parse or are an ExprError at a column inside
// the text (never a crash, a hang or another exception); and whatever parses can be evaluated,
// checked and emitted.
TEST(ExprParserFuzz, RandomAndDamagedExpressions) {
    std::mt19937 rng(99);
    const std::string junk("uv()+-*/^,.e1 $\0", 16);  // with a NUL byte
    int damaged_parsed = 0;
    for (int i = 0; i < 4000; ++i) {
        std::string text = random_expression(rng, 5);
        bool damaged = i % 2 == 1;
        if (damaged) {
            for (int k = std::uniform_int_distribution<int>(1, 3)(rng); k > 0; --k) {
                std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size())(rng);
                if (rng() % 2 && at < text.size()) text.erase(at, 1);
                else text.insert(at, 1, junk[rng() % junk.size()]);
            }
        }
        Expr e;
        try {
            e = parse_expression(text, kParams);
        } catch (const ExprError& error) {
            ASSERT_TRUE(damaged) << text << ": " << error.what();
            ASSERT_GE(error.column, 0) << text;
            ASSERT_LE(error.column, static_cast<int>(text.size())) << text;
            continue;
        }
        damaged_parsed += damaged;
        evaluate(e, 0.3, 0.7);
        evaluate(e, Interval(0.0, 1.0), Interval(0.0, 1.0));
        evaluate(e, Dual<Interval>::variable_u({0.0, 1.0}), Dual<Interval>::variable_v({0.0, 1.0}));
        try {
            check_expression_domain(e, {0.0, 1.0}, {0.0, 1.0});
        } catch (const ExprError& error) {
            ASSERT_GE(error.column, 0);
            ASSERT_LT(error.column, static_cast<int>(text.size()));
        }
        ASSERT_FALSE(gpu::emit_glsl_surface(e, e, e, "surf").empty());
    }
    EXPECT_GT(damaged_parsed, 100);  // the damage is not always fatal, so both paths are exercised
}

}  // namespace
}  // namespace lancer::surface

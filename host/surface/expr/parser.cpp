// Recursive descent over the grammar in parser.hpp. Nodes are appended in post-order as the
// rules return, so the node list is ready to evaluate. Constant operands are folded on the side
// (not in the tree) only to decide which power operation `^` is.
#include "surface/expr/parser.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "core/closest_match.hpp"
#include "surface/expr/evaluate_nodes.hpp"
#include "surface/expr/functions.hpp"
#include "surface/expr/lexer.hpp"

namespace lancer::surface {
namespace {

constexpr double kMaxIntegerExponent = 1 << 20;

struct BuiltinConstant {
    std::string_view name;
    double value;
};
constexpr BuiltinConstant kBuiltinConstants[] = {{"pi", std::numbers::pi}, {"e", std::numbers::e}};

bool is_name(std::string_view s) {
    auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (s.empty() || !letter(s[0])) return false;
    for (char c : s)
        if (!letter(c) && !(c >= '0' && c <= '9')) return false;
    return true;
}

bool is_variable(std::string_view name, Variables variables) {
    for (std::string_view v : variables)
        if (v == name) return true;
    return false;
}

void check_constants(const Constants& constants, Variables variables) {
    for (const auto& [name, value] : constants) {
        if (!is_name(name)) throw UserError(fmt::format("parameter name '{}' is not a name (letters, digits, '_')", name));
        if (is_variable(name, variables))
            throw UserError(fmt::format("parameter '{}' would hide the variable {}", name, name));
        for (const auto& builtin : kBuiltinConstants)
            if (name == builtin.name) throw UserError(fmt::format("parameter '{}' would hide the constant {}", name, name));
        if (find_function(name)) throw UserError(fmt::format("parameter '{}' would hide the function {}", name, name));
        if (!std::isfinite(value)) throw UserError(fmt::format("parameter '{}' must be finite, not {}", name, value));
    }
}

class Parser {
public:
    Parser(std::string_view text, const Constants& constants, Variables variables)
        : constants_(constants), variables_(variables), tokens_(tokenize(text)) {}

    Expr parse() {
        if (peek().kind == TokenKind::End) throw ExprError("empty expression", 0);
        expression();
        const Token& rest = peek();
        if (rest.kind == TokenKind::RightParen) throw ExprError("unmatched ')'", rest.column);
        if (rest.kind != TokenKind::End)
            throw ExprError(fmt::format("unexpected {} after a complete expression (missing operator?)", describe(rest)),
                            rest.column);
        return Expr{std::move(nodes_)};
    }

private:
    const Token& peek() const { return tokens_[position_]; }
    const Token& take() { return tokens_[position_++]; }
    bool accept(TokenKind kind) {
        if (peek().kind != kind) return false;
        ++position_;
        return true;
    }

    // Appends a node; remembers its value when all its operands are constant.
    int add(Node node) {
        std::optional<double> value;
        if (node.op == Op::Constant) {
            value = node.value;
        } else if (node.op != Op::Variable) {
            bool a_constant = node.a < 0 || constant_[node.a].has_value();
            bool b_constant = node.b < 0 || constant_[node.b].has_value();
            if (a_constant && b_constant) {
                double operands[2] = {node.a >= 0 ? *constant_[node.a] : 0.0, node.b >= 0 ? *constant_[node.b] : 0.0};
                Node local = node;
                local.a = node.a >= 0 ? 0 : -1;
                local.b = node.b >= 0 ? 1 : -1;
                value = apply_node<double>(local, operands, nullptr);
            }
        }
        nodes_.push_back(node);
        constant_.push_back(value);
        return static_cast<int>(nodes_.size()) - 1;
    }

    int binary(Op op, int a, int b, int column) { return add({op, a, b, 0.0, column}); }

    // x ^ y: which of the three power operations depends on whether y is a constant integer.
    int power_node(int base, int exponent, int column) {
        const std::optional<double>& c = constant_[exponent];
        if (c && std::isfinite(*c) && *c == std::round(*c) && std::abs(*c) <= kMaxIntegerExponent)
            return add({Op::PowInt, base, exponent, *c, column});
        if (c && std::isfinite(*c)) return add({Op::PowConst, base, exponent, *c, column});
        return add({Op::Pow, base, exponent, 0.0, column});
    }

    int expression() {
        int left = term();
        while (peek().kind == TokenKind::Plus || peek().kind == TokenKind::Minus) {
            const Token& op = take();
            int right = term();
            left = binary(op.kind == TokenKind::Plus ? Op::Add : Op::Sub, left, right, op.column);
        }
        return left;
    }

    int term() {
        int left = unary();
        while (peek().kind == TokenKind::Star || peek().kind == TokenKind::Slash) {
            const Token& op = take();
            int right = unary();
            left = binary(op.kind == TokenKind::Star ? Op::Mul : Op::Div, left, right, op.column);
        }
        return left;
    }

    // Every level of nesting (parentheses, arguments, signs, exponents) passes through here, so
    // this is where the depth limit keeps the recursion, and the stack, bounded.
    int unary() {
        struct DepthGuard {
            int& depth;
            explicit DepthGuard(int& d) : depth(++d) {}
            ~DepthGuard() { --depth; }
        } guard(depth_);
        if (depth_ > kMaxExpressionDepth + 1)  // the whole expression is level 1, not nesting
            throw ExprError(fmt::format("expression is nested too deeply (more than {} levels)", kMaxExpressionDepth),
                            peek().column);
        if (peek().kind == TokenKind::Minus) {
            int column = take().column;
            int operand = unary();
            return add({Op::Neg, operand, -1, 0.0, column});
        }
        if (accept(TokenKind::Plus)) return unary();
        return power();
    }

    int power() {
        int base = primary();
        if (peek().kind == TokenKind::Caret) {
            int column = take().column;
            int exponent = unary();
            return power_node(base, exponent, column);
        }
        return base;
    }

    int primary() {
        const Token& token = peek();
        switch (token.kind) {
            case TokenKind::Number:
                take();
                return add({Op::Constant, -1, -1, token.number, token.column});
            case TokenKind::Name:
                take();
                if (peek().kind == TokenKind::LeftParen) return call(token);
                return name(token);
            case TokenKind::LeftParen: {
                take();
                int inner = expression();
                expect_closing();
                return inner;
            }
            case TokenKind::End:
                throw ExprError("incomplete expression: expected a number, a variable, a function call or '(' at the end",
                                token.column);
            default:
                throw ExprError(fmt::format("expected a number, a variable, a function call or '(', not {}", describe(token)),
                                token.column);
        }
    }

    void expect_closing() {
        if (accept(TokenKind::RightParen)) return;
        const Token& found = peek();
        if (found.kind == TokenKind::End) throw ExprError("missing ')' at the end of the expression", found.column);
        throw ExprError(fmt::format("missing ')' before {}", describe(found)), found.column);
    }

    std::set<std::string, std::less<>> variable_names() const {
        std::set<std::string, std::less<>> names;
        for (std::string_view v : variables_) names.emplace(v);
        for (const auto& builtin : kBuiltinConstants) names.emplace(builtin.name);
        for (const auto& [constant, value] : constants_) names.insert(constant);
        return names;
    }

    int name(const Token& token) {
        std::string_view n = token.text;
        for (std::size_t i = 0; i < variables_.size(); ++i)
            if (n == variables_[i]) return add({Op::Variable, -1, -1, static_cast<double>(i), token.column});
        for (const auto& builtin : kBuiltinConstants)
            if (n == builtin.name) return add({Op::Constant, -1, -1, builtin.value, token.column});
        if (auto found = constants_.find(n); found != constants_.end())
            return add({Op::Constant, -1, -1, found->second, token.column});
        if (find_function(n))
            throw ExprError(fmt::format("'{}' is a function: write {}(...)", n, n), token.column);
        // A one-letter name is within one edit of every other one; suggesting there is noise.
        std::string known = "pi, e";
        for (const auto& [constant, value] : constants_) known += ", " + constant;
        // A scene's numbers have no variables: only named values ([define], clock, ...).
        std::string listed = variables_.empty() ? fmt::format(" (the names are {})", known)
                                                : fmt::format(" (the variables are {}; constants: {})", list_variables(variables_), known);
        std::string ending = n.size() >= 2 ? did_you_mean(n, variable_names(), listed) : listed;
        throw ExprError(fmt::format("unknown {} '{}'", variables_.empty() ? "name" : "variable", n) + ending, token.column);
    }

    int call(const Token& token) {
        std::string_view n = token.text;
        const FunctionInfo* function = find_function(n);
        if (!function) {
            if (is_variable(n, variables_))
                throw ExprError(fmt::format("'{}' is a variable, not a function", n), token.column);
            if (variable_names().count(n))
                throw ExprError(fmt::format("'{}' is a constant, not a function", n), token.column);
            std::set<std::string, std::less<>> names;
            for (const auto& f : function_table()) names.emplace(f.name);
            throw ExprError(fmt::format("unknown function '{}'", n) + did_you_mean(n, names), token.column);
        }
        take();  // '('
        std::vector<int> arguments;
        if (peek().kind != TokenKind::RightParen) {
            arguments.push_back(expression());
            while (accept(TokenKind::Comma)) arguments.push_back(expression());
        }
        expect_closing();
        if (static_cast<int>(arguments.size()) != function->arity)
            throw ExprError(fmt::format("{} takes {} argument{}, not {}", n, function->arity,
                                        function->arity == 1 ? "" : "s", arguments.size()),
                            token.column);
        if (function->op == Op::Pow) return power_node(arguments[0], arguments[1], token.column);
        return add({function->op, arguments[0], function->arity > 1 ? arguments[1] : -1, 0.0, token.column});
    }

    const Constants& constants_;
    Variables variables_;
    std::vector<Token> tokens_;
    std::size_t position_ = 0;
    std::vector<Node> nodes_;
    std::vector<std::optional<double>> constant_;
    int depth_ = 0;
};

}  // namespace

std::string list_variables(Variables variables) {
    std::string out;
    for (std::size_t i = 0; i < variables.size(); ++i) {
        if (i > 0) out += i + 1 == variables.size() ? " and " : ", ";
        out += variables[i];
    }
    return out;
}

Expr parse_expression(std::string_view text, const Constants& constants, Variables variables) {
    check_constants(constants, variables);
    if (text.size() > static_cast<std::size_t>(kMaxExpressionLength))
        throw ExprError(fmt::format("expression is too long ({} characters; the limit is {})", text.size(),
                                    kMaxExpressionLength),
                        kMaxExpressionLength);
    return Parser(text, constants, variables).parse();
}

}  // namespace lancer::surface

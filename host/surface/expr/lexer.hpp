#pragma once
// Splits an expression's text into tokens. Throws ExprError at an unexpected character or a
// malformed number.
#include <string>
#include <string_view>
#include <vector>

namespace lancer::surface {

enum class TokenKind { Number, Name, Plus, Minus, Star, Slash, Caret, LeftParen, RightParen, Comma, End };

struct Token {
    TokenKind kind;
    int column;             // 0-based offset of the token's first character
    std::string_view text;  // a view into the source text
    double number = 0.0;    // for Number
};

std::vector<Token> tokenize(std::string_view text);

// How a token is named in messages: 'sin', '+', the number 2.5, the end of the expression.
std::string describe(const Token& token);

}  // namespace lancer::surface

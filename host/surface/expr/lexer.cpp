#include "surface/expr/lexer.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "surface/expr/expr.hpp"

namespace lancer::surface {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_name_char(char c) { return is_name_start(c) || is_digit(c); }
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string describe_char(char c) {
    auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x21 && byte < 0x7f) return fmt::format("'{}'", c);
    return fmt::format("byte 0x{:02X}", byte);
}

// digits [. digits] [e [+-] digits], or . digits [...]; returns the length, 0 if malformed.
std::size_t scan_number(std::string_view s) {
    std::size_t i = 0, digits = 0;
    while (i < s.size() && is_digit(s[i])) ++i, ++digits;
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && is_digit(s[i])) ++i, ++digits;
    }
    if (digits == 0) return 0;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        std::size_t j = i + 1;
        if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
        std::size_t exponent_digits = 0;
        while (j < s.size() && is_digit(s[j])) ++j, ++exponent_digits;
        if (exponent_digits == 0) return 0;
        i = j;
    }
    return i;
}

TokenKind punctuation(char c) {
    switch (c) {
        case '+': return TokenKind::Plus;
        case '-': return TokenKind::Minus;
        case '*': return TokenKind::Star;
        case '/': return TokenKind::Slash;
        case '^': return TokenKind::Caret;
        case '(': return TokenKind::LeftParen;
        case ')': return TokenKind::RightParen;
        case ',': return TokenKind::Comma;
        default: return TokenKind::End;
    }
}

}  // namespace

std::vector<Token> tokenize(std::string_view text) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < text.size()) {
        char c = text[i];
        int column = static_cast<int>(i);
        if (is_space(c)) {
            ++i;
        } else if (is_digit(c) || c == '.') {
            std::size_t length = scan_number(text.substr(i));
            if (length == 0) {
                std::size_t end = i + 1;
                while (end < text.size() && (is_name_char(text[end]) || text[end] == '.')) ++end;
                throw ExprError(fmt::format("malformed number '{}'", text.substr(i, end - i)), column);
            }
            // from_chars: independent of the locale's decimal point, unlike strtod.
            std::string_view literal = text.substr(i, length);
            double value = 0.0;
            auto [end, error] = std::from_chars(literal.data(), literal.data() + literal.size(), value);
            if (error != std::errc() || end != literal.data() + literal.size() || !std::isfinite(value))
                throw ExprError(fmt::format("number {} is out of range", literal), column);
            tokens.push_back({TokenKind::Number, column, text.substr(i, length), value});
            i += length;
        } else if (is_name_start(c)) {
            std::size_t end = i + 1;
            while (end < text.size() && is_name_char(text[end])) ++end;
            tokens.push_back({TokenKind::Name, column, text.substr(i, end - i)});
            i = end;
        } else if (TokenKind kind = punctuation(c); kind != TokenKind::End) {
            tokens.push_back({kind, column, text.substr(i, 1)});
            ++i;
        } else {
            throw ExprError("unexpected character " + describe_char(c), column);
        }
    }
    tokens.push_back({TokenKind::End, static_cast<int>(text.size()), {}});
    return tokens;
}

std::string describe(const Token& token) {
    switch (token.kind) {
        case TokenKind::Number: return fmt::format("the number {}", token.text);
        case TokenKind::End: return "the end of the expression";
        default: return fmt::format("'{}'", token.text);
    }
}

}  // namespace lancer::surface

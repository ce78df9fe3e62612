#include "scene/string_position.hpp"

#include <cstdlib>

namespace lancer {
namespace {

thread_local const std::string* current_file = nullptr;
thread_local std::string_view current_text;

bool is_continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// Walks the raw text, keeping the line and column (1-based; columns count UTF-8 characters,
// as toml++'s do).
struct Cursor {
    std::string_view text;
    std::size_t at = 0;
    int line = 1;
    int column = 1;

    bool done() const { return at >= text.size(); }
    bool starts_with(std::string_view s) const { return text.substr(at, s.size()) == s; }
    char peek(std::size_t ahead = 0) const { return at + ahead < text.size() ? text[at + ahead] : '\0'; }
    void advance(std::size_t n = 1) {
        for (; n > 0 && !done(); --n, ++at) {
            if (text[at] == '\n') {
                ++line;
                column = 1;
            } else if (!is_continuation(text[at])) {
                ++column;
            }
        }
    }
    bool at_newline() const { return peek() == '\n' || (peek() == '\r' && peek(1) == '\n'); }
    void skip_newline() { advance(peek() == '\r' ? 2 : 1); }
};

// Bytes of the UTF-8 encoding of code point `cp`.
std::size_t utf8_length(unsigned long cp) { return cp < 0x80 ? 1 : cp < 0x800 ? 2 : cp < 0x10000 ? 3 : 4; }

// Moves the cursor to (line, column).
bool seek(Cursor& c, const SourceLocation& where) {
    while (!c.done() && c.line < where.line) c.advance();
    while (!c.done() && c.line == where.line && c.column < where.column) c.advance();
    return c.line == where.line && c.column == where.column;
}

}  // namespace

SourceTextScope::SourceTextScope(const std::string& file, std::string_view text)
    : previous_file_(current_file), previous_text_(current_text) {
    current_file = &file;
    current_text = text;
}

SourceTextScope::~SourceTextScope() {
    current_file = previous_file_;
    current_text = previous_text_;
}

std::string_view source_text(const std::string& file) {
    return current_file && *current_file == file ? current_text : std::string_view{};
}

SourceLocation position_in_string(std::string_view text, const SourceLocation& value, std::size_t index) {
    SourceLocation guess = value;
    guess.column += 1 + static_cast<int>(index);
    Cursor c{text};
    if (!seek(c, value)) return guess;
    const bool basic = c.peek() == '"';
    if (!basic && c.peek() != '\'') return guess;
    const std::string_view delimiter = c.starts_with(basic ? "\"\"\"" : "'''") ? text.substr(c.at, 3) : text.substr(c.at, 1);
    const bool multi_line = delimiter.size() == 3;
    c.advance(delimiter.size());
    if (multi_line && c.at_newline()) c.skip_newline();  // trimmed by TOML

    std::size_t decoded = 0;  // bytes of the value before the cursor
    while (!c.done() && !c.starts_with(delimiter)) {
        if (basic && c.peek() == '\\') {
            // A line-ending backslash swallows the newline and the whitespace after it.
            std::size_t k = 1;
            while (c.peek(k) == ' ' || c.peek(k) == '\t') ++k;
            if (multi_line && (c.peek(k) == '\n' || (c.peek(k) == '\r' && c.peek(k + 1) == '\n'))) {
                c.advance(k);
                while (c.at_newline() || c.peek() == ' ' || c.peek() == '\t') {
                    if (c.at_newline()) c.skip_newline(); else c.advance();
                }
                continue;
            }
            if (decoded >= index) break;
            char kind = c.peek(1);
            if (kind == 'u' || kind == 'U') {
                std::size_t digits = kind == 'u' ? 4 : 8;
                unsigned long cp = std::strtoul(std::string(text.substr(c.at + 2, digits)).c_str(), nullptr, 16);
                decoded += utf8_length(cp);
                c.advance(2 + digits);
            } else {
                decoded += 1;
                c.advance(2);
            }
            continue;
        }
        if (decoded >= index) break;
        // A raw character: all of its bytes are in the value (CRLF becomes LF in it).
        if (c.peek() == '\r' && c.peek(1) == '\n') {
            decoded += 1;
            c.advance(2);
            continue;
        }
        std::size_t bytes = 1;
        while (is_continuation(c.peek(bytes))) ++bytes;
        decoded += bytes;
        c.advance(bytes);
    }
    return {value.file, c.line, c.column};
}

}  // namespace lancer

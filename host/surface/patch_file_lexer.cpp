#include "surface/patch_file_lexer.hpp"

#include <charconv>
#include <cmath>

#include "core/magnitude.hpp"

namespace lancer::surface::detail {
namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == ','; }

// Tokens are quoted in messages; a binary file must not flood the terminal.
std::string quoted(std::string_view s) {
    constexpr std::size_t kMax = 40;
    std::string out = "'" + std::string(s.substr(0, kMax)) + (s.size() > kMax ? "...'" : "'");
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    return out;
}

// from_chars does not take a leading '+'; "+1.5" is a fine number, "+-1" is not.
void strip_plus(std::string_view& s) {
    if (s.size() > 1 && s[0] == '+' && s[1] != '+' && s[1] != '-') s.remove_prefix(1);
}

}  // namespace

PatchLexer::PatchLexer(std::string_view text, std::string file_name) : file_(std::move(file_name)) {
    int line = 1;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        bool last = end == std::string_view::npos;
        std::string_view raw = text.substr(start, last ? std::string_view::npos : end - start);
        std::string_view content = raw.substr(0, raw.find('#'));
        Record r;
        r.line = line;
        for (std::size_t i = 0; i < content.size();) {
            if (is_separator(content[i])) {
                r.has_comma |= content[i] == ',';
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j < content.size() && !is_separator(content[j])) ++j;
            r.tokens.push_back({content.substr(i, j - i), line, static_cast<int>(i) + 1});
            r.end_column = static_cast<int>(j) + 1;
            i = j;
        }
        if (!r.tokens.empty()) records_.push_back(std::move(r));
        if (last) {
            eof_line_ = line;
            eof_column_ = static_cast<int>(raw.size()) + 1;
            break;
        }
        start = end + 1;
        ++line;
    }
}

const Record& PatchLexer::next(const std::string& what_was_expected) {
    if (at_end()) fail_at_eof("file ends early: " + what_was_expected);
    return records_[next_++];
}

void PatchLexer::fail(const Token& at, const std::string& message) const {
    throw SceneError({file_, at.line, at.column}, message);
}

void PatchLexer::fail_at_end_of(const Record& r, const std::string& message) const {
    throw SceneError({file_, r.line, r.end_column}, message);
}

void PatchLexer::fail_at_eof(const std::string& message) const {
    throw SceneError({file_, eof_line_, eof_column_}, message);
}

long long PatchLexer::whole_number(const Token& t, const std::string& what) const {
    std::string_view s = t.text;
    strip_plus(s);
    long long value = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec == std::errc::result_out_of_range) fail(t, what + " is out of range: " + quoted(t.text));
    if (ec != std::errc() || end != s.data() + s.size())
        fail(t, what + " must be a whole number, not " + quoted(t.text));
    return value;
}

double PatchLexer::finite_number(const Token& t, const std::string& what) const {
    std::string_view s = t.text;
    strip_plus(s);
    double value = 0.0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec == std::errc::result_out_of_range) fail(t, what + " is out of range: " + quoted(t.text));
    if (ec != std::errc() || end != s.data() + s.size())
        fail(t, "expected a number (" + what + "), found " + quoted(t.text));
    if (!std::isfinite(value)) fail(t, what + " must be finite, not " + quoted(t.text));
    if (std::abs(value) > kMaxMagnitude)
        fail(t, what + " " + quoted(t.text) + " is beyond lancer's limit of 1e12 for any number");
    return value;
}

}  // namespace lancer::surface::detail

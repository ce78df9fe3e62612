#include "mesh/text_lines.hpp"

#include <charconv>

#include <fmt/format.h>

#include "core/error.hpp"

namespace lancer::mesh {
namespace {

bool is_line_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// from_chars takes no leading '+'; "+1.5" is a fine number, "+-1" is not.
std::string_view without_plus(std::string_view s) {
    if (s.size() > 1 && s[0] == '+' && s[1] != '+' && s[1] != '-') s.remove_prefix(1);
    return s;
}

}  // namespace

std::string excerpt(std::string_view s) {
    constexpr std::size_t kMax = 40;
    std::string out = "'" + std::string(s.substr(0, kMax)) + (s.size() > kMax ? "...'" : "'");
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    return out;
}

bool TextLines::next() {
    while (pos_ < text_.size()) {
        std::size_t end = text_.find('\n', pos_);
        if (end == std::string_view::npos) end = text_.size();
        current_ = text_.substr(pos_, end - pos_);
        pos_ = end + 1;
        ++line_;
        const std::string_view content = current_.substr(0, current_.find('#'));
        tokens_.clear();
        for (std::size_t i = 0; i < content.size();) {
            if (is_line_blank(content[i])) {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j < content.size() && !is_line_blank(content[j])) ++j;
            tokens_.push_back({content.substr(i, j - i), static_cast<int>(i) + 1});
            i = j;
        }
        if (!tokens_.empty()) return true;
    }
    return false;
}

std::string_view TextLines::rest_from(std::size_t first) const {
    const LineToken& t = tokens_.at(first);
    const LineToken& last = tokens_.back();
    const std::size_t begin = static_cast<std::size_t>(t.column - 1);
    const std::size_t end = static_cast<std::size_t>(last.column - 1) + last.text.size();
    return current_.substr(begin, end - begin);
}

void TextLines::fail(const LineToken& at, const std::string& message) const {
    throw SceneError({file_, line_, at.column}, message);
}

void TextLines::fail_at_line(const std::string& message) const { throw SceneError({file_, line_, 0}, message); }

void TextLines::fail_after_last(const std::string& message) const {
    const LineToken& last = tokens_.back();
    throw SceneError({file_, line_, last.column + static_cast<int>(last.text.size())}, message);
}

double TextLines::number(const LineToken& t, const std::string& what) const {
    const std::string_view s = without_plus(t.text);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec == std::errc::result_out_of_range) fail(t, fmt::format("{} {} is out of range", what, excerpt(t.text)));
    if (ec != std::errc() || end != s.data() + s.size())
        fail(t, fmt::format("expected a number for the {}, found {}", what, excerpt(t.text)));
    return value;
}

long long TextLines::integer(const LineToken& t, std::string_view digits, const std::string& what) const {
    const std::string_view s = without_plus(digits);
    long long value = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec == std::errc::result_out_of_range) fail(t, fmt::format("{} {} is out of range", what, excerpt(digits)));
    if (ec != std::errc() || end != s.data() + s.size() || s.empty())
        fail(t, fmt::format("expected a whole number for the {}, found {}", what, excerpt(digits)));
    return value;
}

}  // namespace lancer::mesh

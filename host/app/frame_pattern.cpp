#include "app/frame_pattern.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>

#include <fmt/format.h>

#include "core/error.hpp"

namespace lancer {
namespace {

[[noreturn]] void bad_pattern(const std::string& text, const std::string& why) {
    throw UserError(fmt::format("-o {}: {}", text, why));
}

// Parses a whole string as a non-negative int; nullopt for anything else.
std::optional<int> whole_number(std::string_view s) {
    int value = 0;
    if (s.empty()) return std::nullopt;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec != std::errc() || end != s.data() + s.size() || value < 0) return std::nullopt;
    return value;
}

}  // namespace

std::optional<FramePattern> FramePattern::parse(const std::string& text) {
    FramePattern p;
    p.text_ = text;
    bool found = false;
    std::string* out = &p.prefix_;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '%') {
            *out += text[i];
            continue;
        }
        if (i + 1 < text.size() && text[i + 1] == '%') {
            *out += '%';
            ++i;
            continue;
        }
        // %d or %0Nd
        std::size_t j = i + 1;
        int width = 0;
        if (j < text.size() && text[j] == '0') {
            std::size_t k = j + 1;
            while (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) ++k;
            auto n = whole_number(std::string_view(text).substr(j + 1, k - j - 1));
            if (!n || *n < 1 || *n > 9) bad_pattern(text, "the width in %0Nd must be 1 to 9");
            width = *n;
            j = k;
        }
        if (j >= text.size() || text[j] != 'd')
            bad_pattern(text, "'" + text.substr(i, std::min(j + 1, text.size()) - i) +
                                  "' is not a frame number (use %d or %0Nd, and %% for a literal %)");
        if (found) bad_pattern(text, "two frame numbers; a frame pattern has one");
        found = true;
        p.width_ = width;
        out = &p.suffix_;
        i = j;
    }
    if (!found) return std::nullopt;
    if (p.suffix_.find('/') != std::string::npos)
        bad_pattern(text, "the frame number must be in the file name, not in a directory");
    return p;
}

std::string FramePattern::path(int frame) const {
    return fmt::format("{}{:0{}d}{}", prefix_, frame, width_, suffix_);
}

std::string FramePattern::directory() const {
    return std::filesystem::path(prefix_ + "0" + suffix_).parent_path().string();
}

bool has_frame_field(const std::string& text) {
    try {
        return FramePattern::parse(text).has_value();
    } catch (const UserError&) {
        return false;  // a % that is no frame field is an ordinary character of a still's name
    }
}

int frame_number_width(int frames) {
    int width = 1;
    for (int last = frames - 1; last >= 10; last /= 10) ++width;
    return width;
}

std::string frame_field(int frames) {
    int width = frame_number_width(frames);
    return width == 1 ? "%d" : fmt::format("%0{}d", width);
}

std::string default_frame_pattern(const std::string& scene_path, int frames) {
    std::string stem = std::filesystem::path(scene_path).stem().string();
    std::string escaped;
    for (char c : stem) escaped += c == '%' ? std::string("%%") : std::string(1, c);
    return escaped + "_" + frame_field(frames) + ".png";
}

FrameRange parse_frame_range(const std::string& text, int frames) {
    std::string valid = frames == 1 ? "the animation has 1 frame, 0" : fmt::format("the animation has {} frames, 0-{}", frames, frames - 1);
    FrameRange r;
    std::size_t dash = text.find('-');
    std::optional<int> first, last;
    if (dash == std::string::npos) {
        first = last = whole_number(text);
    } else {
        first = whole_number(std::string_view(text).substr(0, dash));
        last = whole_number(std::string_view(text).substr(dash + 1));
    }
    if (!first || !last) throw UserError(fmt::format("--frames {}: expected A-B or N, frame numbers from 0 ({})", text, valid));
    if (*first > *last) throw UserError(fmt::format("--frames {}: the first frame comes after the last", text));
    if (*last >= frames) throw UserError(fmt::format("--frames {}: {}", text, valid));
    r.first = *first;
    r.last = *last;
    return r;
}

std::string format_frame_list(const std::vector<int>& frames) {
    std::string out;
    for (std::size_t i = 0; i < frames.size();) {
        std::size_t j = i;
        while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
        if (!out.empty()) out += ", ";
        out += j == i ? fmt::format("{}", frames[i]) : fmt::format("{}-{}", frames[i], frames[j]);
        i = j + 1;
    }
    return out;
}

}  // namespace lancer

#include "mesh/ply_values.hpp"

#include <algorithm>
#include <charconv>
#include <cstring>

#include <fmt/format.h>

#include "core/error.hpp"
#include "mesh/text_lines.hpp"

namespace lancer::mesh {
namespace {

bool is_data_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

template <class T>
T load(const unsigned char* p, bool big_endian) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, p, sizeof(T));
    if (big_endian)
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    T value;
    std::memcpy(&value, b, sizeof(T));
    return value;
}

}  // namespace

PlyValues::PlyValues(std::string_view bytes, const PlyHeader& header, std::string file)
    : bytes_(bytes), format_(header.format), file_(std::move(file)), pos_(header.data_offset),
      value_start_(header.data_offset), line_(header.data_line), line_start_(header.data_offset),
      token_line_(header.data_line - 1) {}

void PlyValues::set_item(const std::string& element, std::uint64_t index, std::uint64_t count) {
    if (element_ != element) element_ = element;
    index_ = index;
    count_ = count;
}

void PlyValues::fail(const std::string& message) const {
    if (binary()) throw SceneError({file_, 0, 0}, fmt::format("byte {}: {}", value_start_, message));
    throw SceneError({file_, line_, column_}, message);
}

void PlyValues::fail_early_end() const {
    const std::string what = fmt::format("the file ends early, in {} {} of the {} the header declares", element_,
                                         index_ + 1, count_);
    if (binary()) throw SceneError({file_, 0, 0}, fmt::format("byte {}: {}", bytes_.size(), what));
    throw SceneError({file_, token_line_, 0}, what);
}

std::string_view PlyValues::next_token() {
    while (pos_ < bytes_.size() && is_data_blank(bytes_[pos_])) {
        if (bytes_[pos_] == '\n') {
            ++line_;
            line_start_ = pos_ + 1;
        }
        ++pos_;
    }
    if (pos_ >= bytes_.size()) fail_early_end();
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !is_data_blank(bytes_[pos_])) ++pos_;
    value_start_ = start;
    token_line_ = line_;
    column_ = static_cast<int>(start - line_start_) + 1;
    token_ = bytes_.substr(start, pos_ - start);
    return token_;
}

const unsigned char* PlyValues::take(std::size_t n) {
    value_start_ = pos_;
    if (bytes_.size() - pos_ < n) fail_early_end();
    const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data() + pos_);
    pos_ += n;
    return p;
}

std::int64_t PlyValues::ascii_integer(std::string_view s) {
    std::string_view digits = s;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range) fail(fmt::format("the whole number {} is out of range", excerpt(s)));
    if (ec != std::errc() || end != digits.data() + digits.size())
        fail(fmt::format("expected a whole number (the header declares an integer type), found {}", excerpt(s)));
    return value;
}

double PlyValues::number(PlyScalar t) {
    if (!binary()) {
        const std::string_view s = next_token();
        if (is_integer(t)) return static_cast<double>(ascii_integer(s));
        std::string_view digits = s;
        if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
        double x = 0.0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), x);
        if (ec == std::errc::result_out_of_range) fail(fmt::format("the number {} is out of range", excerpt(s)));
        if (ec != std::errc() || end != digits.data() + digits.size()) fail(fmt::format("expected a number, found {}", excerpt(s)));
        return x;
    }
    const bool big = format_ == PlyFormat::binary_big_endian;
    const unsigned char* p = take(size_of(t));
    switch (t) {
        case PlyScalar::int8: return static_cast<std::int8_t>(*p);
        case PlyScalar::uint8: return *p;
        case PlyScalar::int16: return load<std::int16_t>(p, big);
        case PlyScalar::uint16: return load<std::uint16_t>(p, big);
        case PlyScalar::int32: return load<std::int32_t>(p, big);
        case PlyScalar::uint32: return load<std::uint32_t>(p, big);
        case PlyScalar::float32: return load<float>(p, big);
        case PlyScalar::float64: return load<double>(p, big);
    }
    return 0.0;
}

std::int64_t PlyValues::integer(PlyScalar t) {
    if (!binary()) return ascii_integer(next_token());
    // Integer types only (the reader checks the header): every value is exact in a double.
    return static_cast<std::int64_t>(number(t));
}

void PlyValues::skip(PlyScalar t) {
    if (binary())
        take(size_of(t));
    else
        next_token();
}

std::uint64_t PlyValues::list_length(const PlyProperty& p) {
    const std::int64_t n = integer(p.count_type);
    if (n < 0) fail(fmt::format("a list of {} entries", n));
    if (static_cast<std::uint64_t>(n) > bytes_left())
        fail(fmt::format("a list of {} entries, but only {} bytes are left in the file", n, bytes_left()));
    return static_cast<std::uint64_t>(n);
}

void PlyValues::skip_list(const PlyProperty& p) {
    const std::uint64_t n = list_length(p);
    for (std::uint64_t i = 0; i < n; ++i) skip(p.type);
}

void PlyValues::skip_element(const PlyElement& e) {
    if (e.properties.empty()) return;  // its items hold nothing: any count of them takes no bytes, and no time
    for (std::uint64_t k = 0; k < e.count; ++k) {
        set_item(e.name, k, e.count);
        for (const PlyProperty& p : e.properties) p.is_list ? skip_list(p) : skip(p.type);
    }
}

std::size_t PlyValues::least_bytes_per_item(const PlyElement& e) const {
    std::size_t n = 0;
    for (const PlyProperty& p : e.properties) n += binary() ? size_of(p.is_list ? p.count_type : p.type) : 2;  // ascii: a digit and a blank
    return n;
}

void PlyValues::refuse_what_cannot_fit(const PlyElement& e) const {
    const std::size_t least = least_bytes_per_item(e);
    if (least == 0 || e.count == 0) return;
    const std::size_t left = bytes_left() + (binary() ? 0 : 1);  // ascii: no blank after the last
    if (e.count > left / least)
        throw SceneError({file_, e.line, 0}, fmt::format("the header declares {} {} items of at least {} bytes each, but only {} "
                                                         "bytes of data follow it (the file is truncated, or the count is wrong)",
                                                         e.count, e.name, least, bytes_left()));
}

std::size_t PlyValues::capacity_for(const PlyElement& e) const {
    return static_cast<std::size_t>(std::min<std::uint64_t>(e.count, bytes_left() / std::max<std::size_t>(1, least_bytes_per_item(e)) + 1));
}

void PlyValues::require_end() {
    if (binary()) {
        value_start_ = pos_;
        if (pos_ != bytes_.size())
            fail(fmt::format("{} bytes after the last element the header declares", bytes_.size() - pos_));
        return;
    }
    while (pos_ < bytes_.size() && is_data_blank(bytes_[pos_])) {
        if (bytes_[pos_] == '\n') {
            ++line_;
            line_start_ = pos_ + 1;
        }
        ++pos_;
    }
    if (pos_ == bytes_.size()) return;
    column_ = static_cast<int>(pos_ - line_start_) + 1;
    fail("text after the last element the header declares");
}

}  // namespace lancer::mesh

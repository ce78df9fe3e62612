#include "mesh/ply_header.hpp"

#include <charconv>

#include <fmt/format.h>

#include "core/error.hpp"
#include "mesh/text_lines.hpp"

namespace lancer::mesh {
namespace {

struct ScalarName {
    std::string_view name;
    PlyScalar type;
};
constexpr ScalarName kScalarNames[] = {
    {"char", PlyScalar::int8},     {"int8", PlyScalar::int8},       {"uchar", PlyScalar::uint8},
    {"uint8", PlyScalar::uint8},   {"short", PlyScalar::int16},     {"int16", PlyScalar::int16},
    {"ushort", PlyScalar::uint16}, {"uint16", PlyScalar::uint16},   {"int", PlyScalar::int32},
    {"int32", PlyScalar::int32},   {"uint", PlyScalar::uint32},     {"uint32", PlyScalar::uint32},
    {"float", PlyScalar::float32}, {"float32", PlyScalar::float32}, {"double", PlyScalar::float64},
    {"float64", PlyScalar::float64}};

// The header is short and plain ASCII; a binary file's data starts right after its last line.
constexpr std::size_t kMaxHeaderBytes = 1 << 20;

}  // namespace

std::size_t size_of(PlyScalar t) {
    switch (t) {
        case PlyScalar::int8:
        case PlyScalar::uint8: return 1;
        case PlyScalar::int16:
        case PlyScalar::uint16: return 2;
        case PlyScalar::int32:
        case PlyScalar::uint32:
        case PlyScalar::float32: return 4;
        case PlyScalar::float64: return 8;
    }
    return 8;
}

int find_scalar(const PlyElement& e, std::initializer_list<std::string_view> names) {
    for (std::size_t i = 0; i < e.properties.size(); ++i)
        for (std::string_view n : names)
            if (e.properties[i].name == n && !e.properties[i].is_list) return static_cast<int>(i);
    return kNoProperty;
}

bool is_integer(PlyScalar t) { return t != PlyScalar::float32 && t != PlyScalar::float64; }

const char* name_of(PlyScalar t) {
    for (const ScalarName& s : kScalarNames)
        if (s.type == t) return s.name.data();
    return "?";
}

PlyHeader read_ply_header(std::string_view bytes, const std::string& file) {
    const std::size_t end_marker = bytes.substr(0, kMaxHeaderBytes).find("end_header");
    // The header's text: up to and including the end_header line.
    std::size_t header_end = std::string_view::npos;
    if (end_marker != std::string_view::npos) header_end = bytes.find('\n', end_marker);
    if (!bytes.starts_with("ply")) throw SceneError({file, 1, 1}, "not a PLY file: it does not start with 'ply'");
    if (header_end == std::string_view::npos)
        throw SceneError({file, 0, 0}, fmt::format("the PLY header has no end_header line{}",
                                                   bytes.size() > kMaxHeaderBytes ? " in its first MiB" : ""));
    TextLines lines(bytes.substr(0, header_end + 1), file);
    PlyHeader header;
    header.data_offset = header_end + 1;
    bool seen_format = false, seen_end = false;
    lines.next();
    if (lines.tokens().size() != 1 || lines.tokens()[0].text != "ply")
        lines.fail(lines.tokens()[0], "not a PLY file: the first line must be 'ply' alone");
    auto scalar = [&](const LineToken& t) {
        for (const ScalarName& s : kScalarNames)
            if (s.name == t.text) return s.type;
        lines.fail(t, fmt::format("unknown property type {}", excerpt(t.text)));
    };
    while (lines.next()) {
        const auto& tok = lines.tokens();
        const std::string_view key = tok[0].text;
        if (seen_end) lines.fail(tok[0], "text after end_header inside the header");
        if (key == "comment" || key == "obj_info") continue;
        if (key == "end_header") {
            if (!seen_format) lines.fail(tok[0], "end_header before the format line");
            seen_end = true;
            header.data_line = lines.line() + 1;
            continue;
        }
        if (!seen_format && key != "format") lines.fail(tok[0], "the second line of a PLY header must be its format");
        if (key == "format") {
            if (seen_format) lines.fail(tok[0], "a second format line");
            if (tok.size() != 3) lines.fail(tok[0], "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
            if (tok[1].text == "ascii")
                header.format = PlyFormat::ascii;
            else if (tok[1].text == "binary_little_endian")
                header.format = PlyFormat::binary_little_endian;
            else if (tok[1].text == "binary_big_endian")
                header.format = PlyFormat::binary_big_endian;
            else
                lines.fail(tok[1], fmt::format("unknown PLY format {}: expected ascii, binary_little_endian or binary_big_endian",
                                               excerpt(tok[1].text)));
            if (tok[2].text != "1.0" && tok[2].text != "1")
                lines.fail(tok[2], fmt::format("PLY version {} is not supported (only 1.0)", excerpt(tok[2].text)));
            seen_format = true;
        } else if (key == "element") {
            if (tok.size() != 3) lines.fail(tok[0], "expected 'element NAME COUNT'");
            PlyElement& e = header.elements.emplace_back();
            e.name = std::string(tok[1].text);
            e.line = lines.line();
            const std::string_view digits = tok[2].text;
            const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), e.count);
            if (ec != std::errc() || end != digits.data() + digits.size())
                lines.fail(tok[2], fmt::format("the count of element {} must be a whole number of at least 0, not {}",
                                               excerpt(e.name), excerpt(digits)));
        } else if (key == "property") {
            if (header.elements.empty()) lines.fail(tok[0], "a property before the first element");
            PlyProperty p;
            p.line = lines.line();
            if (tok.size() >= 2 && tok[1].text == "list") {
                if (tok.size() != 5) lines.fail(tok[0], "expected 'property list COUNT_TYPE ENTRY_TYPE NAME'");
                p.is_list = true;
                p.count_type = scalar(tok[2]);
                if (!is_integer(p.count_type)) lines.fail(tok[2], "a list's count type must be an integer type");
                p.type = scalar(tok[3]);
                p.name = std::string(tok[4].text);
            } else {
                if (tok.size() != 3) lines.fail(tok[0], "expected 'property TYPE NAME'");
                p.type = scalar(tok[1]);
                p.name = std::string(tok[2].text);
            }
            header.elements.back().properties.push_back(std::move(p));
        } else {
            lines.fail(tok[0], fmt::format("unknown PLY header line {}", excerpt(key)));
        }
    }
    return header;
}

}  // namespace lancer::mesh

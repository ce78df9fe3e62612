#pragma once
// A PLY file's header: its format and its elements with their properties, as declared; and the
// byte where the data begins. Errors are at file:line of the header.
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace lancer::mesh {

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };
enum class PlyScalar { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::size_t size_of(PlyScalar t);
bool is_integer(PlyScalar t);
const char* name_of(PlyScalar t);

struct PlyProperty {
    std::string name;
    PlyScalar type = PlyScalar::float32;  // a list's entries
    bool is_list = false;
    PlyScalar count_type = PlyScalar::uint8;  // a list's length
    int line = 0;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
    int line = 0;
};

struct PlyHeader {
    PlyFormat format = PlyFormat::ascii;
    std::vector<PlyElement> elements;
    std::size_t data_offset = 0;  // the byte after end_header's line
    int data_line = 0;            // its line, for ascii
};

// The index in e.properties of the first scalar property with one of these names, or
// kNoProperty.
constexpr int kNoProperty = -1;
int find_scalar(const PlyElement& e, std::initializer_list<std::string_view> names);

PlyHeader read_ply_header(std::string_view bytes, const std::string& file);

}  // namespace lancer::mesh

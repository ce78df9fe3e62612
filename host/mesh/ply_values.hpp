#pragma once
// The values of a PLY file's data, one at a time, in the header's types: numbers separated by
// blanks (ascii) or packed bytes in either byte order (binary). Errors say where: line and column
// of the number for ascii, "byte N" for binary.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/ply_header.hpp"

namespace lancer::mesh {

class PlyValues {
public:
    PlyValues(std::string_view bytes, const PlyHeader& header, std::string file);

    // What is being read, for the message when the data ends early: "vertex 17 of 1000".
    void set_item(const std::string& element, std::uint64_t index, std::uint64_t count);

    double number(PlyScalar t);
    // A whole number (list lengths, indices); for ascii the text must be one.
    std::int64_t integer(PlyScalar t);
    void skip(PlyScalar t);
    // A list's length, refused where negative or longer than the bytes left (each entry takes at
    // least one: a length beyond them is a truncated file, not a reason to wait).
    std::uint64_t list_length(const PlyProperty& p);
    void skip_list(const PlyProperty& p);
    // Every item of an element the reader does not use.
    void skip_element(const PlyElement& e);
    // Item k of element e: each scalar property i with slot[i] >= 0 is read and handed to
    // take(slot[i], property, value); the others, and lists, are read past.
    template <class Take>
    void read_scalars(const PlyElement& e, std::uint64_t k, const std::vector<int>& slot, Take&& take) {
        set_item(e.name, k, e.count);
        for (std::size_t i = 0; i < e.properties.size(); ++i) {
            const PlyProperty& p = e.properties[i];
            if (p.is_list) skip_list(p);
            else if (slot[i] < 0) skip(p.type);
            else take(slot[i], p, number(p.type));
        }
    }

    // Each item of an element takes at least this many bytes: its scalars, its lists' lengths.
    std::size_t least_bytes_per_item(const PlyElement& e) const;
    // A header may declare any count; the items must still fit in what is left of the file:
    // a SceneError at the element's header line where they cannot.
    void refuse_what_cannot_fit(const PlyElement& e) const;
    // How many of e's items to make room for: its count, at most what the bytes left can hold.
    std::size_t capacity_for(const PlyElement& e) const;

    bool binary() const { return format_ != PlyFormat::ascii; }
    std::size_t bytes_left() const { return bytes_.size() - pos_; }
    // Throws unless only blanks are left.
    void require_end();

    // A SceneError at the value read last (the start of the value in binary).
    [[noreturn]] void fail(const std::string& message) const;

private:
    std::string_view next_token();
    std::int64_t ascii_integer(std::string_view s);
    const unsigned char* take(std::size_t n);
    [[noreturn]] void fail_early_end() const;

    std::string_view bytes_;
    PlyFormat format_;
    std::string file_;
    std::size_t pos_;
    std::size_t value_start_;
    int line_, column_ = 0;          // ascii: where the last token starts
    std::size_t line_start_;         // ascii: the byte that starts line_
    int token_line_;                 // ascii: the line of the last token (of end_header before any)
    std::string_view token_;
    std::string element_;
    std::uint64_t index_ = 0, count_ = 0;
};

}  // namespace lancer::mesh

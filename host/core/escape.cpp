#include "core/escape.hpp"

#include <fmt/format.h>

namespace lancer {

std::string escape_control_characters(std::string_view text, bool keep_newlines) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte != 0x7f) {
            out += c;
            continue;
        }
        switch (c) {
            case '\n': out += keep_newlines ? "\n" : "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            case '\0': out += "\\0"; break;
            default: out += fmt::format("\\x{:02x}", byte);
        }
    }
    return out;
}

}  // namespace lancer

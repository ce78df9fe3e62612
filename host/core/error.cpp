#include "core/error.hpp"

#include <cstdio>
#include <sstream>

#include "core/escape.hpp"

namespace lancer {

void print_error(const std::exception& e) { std::fprintf(stderr, "%s\n", format_error(e).c_str()); }

std::string format_error(const std::exception& e) {
    std::ostringstream out;
    if (const auto* scene = dynamic_cast<const SceneError*>(&e)) {
        const SourceLocation& at = scene->where();
        out << (at.file.empty() ? "lancer" : escape_control_characters(at.file.str()));
        if (at.line > 0) {
            out << ':' << at.line;
            if (at.column > 0) out << ':' << at.column;
        }
    } else {
        out << "lancer";
    }
    out << ": error: " << escape_control_characters(e.what(), dynamic_cast<const MultiLineUserError*>(&e) != nullptr);
    return out.str();
}

}  // namespace lancer

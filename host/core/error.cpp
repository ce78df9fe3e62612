#include "core/error.hpp"

#include <sstream>

namespace lancer {

std::string format_error(const std::exception& e) {
    std::ostringstream out;
    if (const auto* scene = dynamic_cast<const SceneError*>(&e)) {
        const SourceLocation& at = scene->where();
        out << (at.file.empty() ? "lancer" : at.file);
        if (at.line > 0) {
            out << ':' << at.line;
            if (at.column > 0) out << ':' << at.column;
        }
    } else {
        out << "lancer";
    }
    out << ": error: " << e.what();
    return out.str();
}

}  // namespace lancer

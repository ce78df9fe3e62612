#include "view/key_bindings.hpp"

namespace lancer::view {

const std::vector<KeyHelp>& key_help() {
    static const std::vector<KeyHelp> rows = {
        {"arrows", "move the camera right / left / up / down"},
        {"q / d", "orbit the look-at point, left / right"},
        {"w / x", "roll anticlockwise / clockwise"},
        {"+ / -", "dolly in / out (also the wheel)"},
        {"drag", "orbit (left mouse button)"},
        {"f", "record the orbit sequence (again: stop)"},
        {"l", "record the moving light (again: stop)"},
        {"p", "save the view as a PNG at full quality"},
        {"r", "reset the camera to the scene's"},
        {"h", "show / hide this help"},
        {"esc", "quit"},
    };
    return rows;
}

}  // namespace lancer::view

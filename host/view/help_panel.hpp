#pragma once
// The help overlay (h) for a window of a given size, drawn in the window's own pixels so that it
// stays readable however the picture is scaled: the key table at twice the font's size where
// that fits, else at its size; in a window too small for the table, a short note saying so.
// The panel always lies wholly inside the window, with a gap on every side; in a window too
// small even for the note it is empty.
#include <string>
#include <vector>

#include "view/bitmap_font.hpp"

namespace lancer::view {

inline constexpr const char* kHelpTooSmall = "window too small for the help: h hides it";

struct HelpPanel {
    bool note = false;               // the note rather than the key table
    int scale = 1;                   // screen pixels per font pixel
    int x = 0, y = 0;                // where its top-left corner goes in the window
    std::vector<std::string> lines;  // the text, line by line (table rows: keys, padding, action)
    Canvas canvas{0, 0};             // translucent black with the text; 0 x 0 when nothing fits
};

HelpPanel help_panel(int window_width, int window_height);

}  // namespace lancer::view

#include "view/help_panel.hpp"

#include <algorithm>
#include <sstream>

#include "view/key_bindings.hpp"

namespace lancer::view {
namespace {

constexpr std::uint32_t kVeil = 0x000000c0u;  // translucent black
constexpr std::uint32_t kKeyColour = 0xffd070ffu;
constexpr std::uint32_t kTextColour = 0xffffffffu;

// The panel's gap to the window's edges and its inner margin, per font pixel of scale.
constexpr int kGap = 4, kMargin = 3;

int lines_height(std::size_t lines, int scale) {
    return lines == 0 ? 0 : (int(lines - 1) * kLineAdvance + kGlyphHeight) * scale;
}

// `text` in lines of at most `max_chars` characters, broken between words; empty when a word is
// longer than that.
std::vector<std::string> wrap(const std::string& text, int max_chars) {
    std::vector<std::string> lines;
    std::istringstream words(text);
    for (std::string word; words >> word;) {
        if (int(word.size()) > max_chars) return {};
        if (!lines.empty() && int(lines.back().size() + 1 + word.size()) <= max_chars)
            lines.back() += " " + word;
        else
            lines.push_back(word);
    }
    return lines;
}

// Whether a panel of `lines` at `scale` fits the window, with its gap on every side.
bool fits(const std::vector<std::string>& lines, int scale, int window_w, int window_h) {
    std::size_t chars = 0;
    for (const auto& l : lines) chars = std::max(chars, l.size());
    int w = text_width(std::string(chars, 'x'), scale) + 2 * kMargin * scale;
    int h = lines_height(lines.size(), scale) + 2 * kMargin * scale;
    return !lines.empty() && w + 2 * kGap * scale <= window_w && h + 2 * kGap * scale <= window_h;
}

HelpPanel blank_panel(std::vector<std::string> lines, int scale, bool note) {
    HelpPanel p;
    p.note = note;
    p.scale = scale;
    p.x = p.y = kGap * scale;
    std::size_t chars = 0;
    for (const auto& l : lines) chars = std::max(chars, l.size());
    p.canvas = Canvas(text_width(std::string(chars, 'x'), scale) + 2 * kMargin * scale,
                      lines_height(lines.size(), scale) + 2 * kMargin * scale);
    p.canvas.fill(kVeil);
    p.lines = std::move(lines);
    return p;
}

}  // namespace

HelpPanel help_panel(int window_width, int window_height) {
    const auto& rows = key_help();
    std::size_t key_chars = 0;
    for (const auto& r : rows) key_chars = std::max(key_chars, r.keys.size());
    std::vector<std::string> table;
    for (const auto& r : rows) table.push_back(r.keys + std::string(key_chars + 2 - r.keys.size(), ' ') + r.action);

    for (int scale : {2, 1}) {
        if (!fits(table, scale, window_width, window_height)) continue;
        HelpPanel p = blank_panel(table, scale, false);
        int margin = kMargin * scale, y = margin;
        for (const auto& r : rows) {
            draw_text(p.canvas, margin, y, r.keys, scale, kKeyColour);
            draw_text(p.canvas, margin + int(key_chars + 2) * kGlyphAdvance * scale, y, r.action, scale, kTextColour);
            y += kLineAdvance * scale;
        }
        return p;
    }
    // The widest lines the window allows: text_width(n) = n * advance - 1.
    int max_chars = (window_width - 2 * (kGap + kMargin) + 1) / kGlyphAdvance;
    std::vector<std::string> note = wrap(kHelpTooSmall, max_chars);
    if (!fits(note, 1, window_width, window_height)) {
        HelpPanel none;
        none.note = true;
        return none;
    }
    HelpPanel p = blank_panel(note, 1, true);
    for (std::size_t i = 0; i < note.size(); ++i)
        draw_text(p.canvas, kMargin, kMargin + int(i) * kLineAdvance, note[i], 1, kTextColour);
    return p;
}

}  // namespace lancer::view

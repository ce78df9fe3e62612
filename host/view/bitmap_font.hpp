#pragma once
// A 5 x 7 pixel font built into the binary, for the viewer's on-screen help: no font files to
// find, no extra package. Upper case, digits and the punctuation the help uses; lower case is
// drawn as upper case.
#include <cstdint>
#include <string>
#include <vector>

namespace lancer::view {

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kGlyphAdvance = 6;  // one column of space between letters
constexpr int kLineAdvance = 10;

// An RGBA canvas, row-major, 4 bytes a pixel (the layout of SDL_PIXELFORMAT_ABGR8888 on little
// endian machines, i.e. bytes R, G, B, A).
struct Canvas {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
    Canvas(int w, int h) : width(w), height(h), rgba(std::size_t(w) * h * 4, 0) {}
    void fill(std::uint32_t rgba_value);
};

// True when `c` has a glyph of its own (others are drawn as '?').
bool has_glyph(char c);

// Draws `text` with its top-left corner at (x, y), each font pixel `scale` x `scale` screen
// pixels; clipped to the canvas.
void draw_text(Canvas& canvas, int x, int y, const std::string& text, int scale, std::uint32_t rgba);

int text_width(const std::string& text, int scale);

}  // namespace lancer::view

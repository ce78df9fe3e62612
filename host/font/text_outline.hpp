#pragma once
// The outline of a line of text in a TrueType or OpenType font (FreeType reads the file), laid out
// as POV-Ray's text object lays out its glyphs: one unit per em, the baseline on the x axis, the
// first glyph's left edge at x = 0, each next glyph at the previous one's advance plus the font's
// kerning plus the caller's offset. Inside is the even-odd rule over all the contours, as POV-Ray's.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "core/error.hpp"

namespace lancer::font {

// One piece of a contour: a Bézier curve of degree 1 (a line), 2 (TrueType's) or 3 (CFF's), its
// control points in em units, points[0..degree] used.
struct OutlineSegment {
    int degree = 1;
    std::array<glm::dvec2, 4> points{};
};

struct TextOutline {
    std::vector<OutlineSegment> segments;  // every glyph's contours, closed, in order
    glm::dvec2 min{0.0}, max{0.0};         // the control points' box (empty text: both 0)
    int glyphs = 0;                        // glyphs with an outline (spaces have none)
};

// A font file that cannot be read as a font of outlines (the file's fault, not the text's).
class FontFileError : public UserError {
public:
    using UserError::UserError;
};

// The text's outline in the font at `font_path`, each glyph after the first moved on by `offset`
// (POV-Ray's text offset) besides its advance. Throws FontFileError for a file FreeType cannot
// read, UserError for a character the font has no glyph for (naming it and its code point) or
// UTF-8 that is not.
TextOutline outline_text(const std::string& font_path, std::string_view utf8, glm::dvec2 offset);

// The code points of UTF-8 text; throws UserError at the first byte that is not UTF-8.
std::u32string decode_utf8(std::string_view utf8);

}  // namespace lancer::font

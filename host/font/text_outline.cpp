#include "font/text_outline.hpp"

#include <algorithm>
#include <cstdint>

#include <fmt/format.h>
#include <glm/common.hpp>
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "core/error.hpp"

namespace lancer::font {
namespace {

// FreeType's messages, by its documented way of building them from its list of errors (Debian's
// FreeType is built without FT_Error_String's).
struct FreeTypeMessage {
    int code;
    const char* text;
};
#undef FTERRORS_H_
#define FT_ERRORDEF(e, v, s) {v, s},
#define FT_ERROR_START_LIST {
#define FT_ERROR_END_LIST {0, nullptr}};
constexpr FreeTypeMessage kFreeTypeMessages[] =
#include FT_ERRORS_H

std::string reason(FT_Error error) {
    for (const FreeTypeMessage* m = kFreeTypeMessages; m->text; ++m)
        if (m->code == error) return m->text;
    return fmt::format("FreeType error {:#x}", error);
}

class Library {
public:
    Library() {
        if (FT_Error e = FT_Init_FreeType(&handle_)) throw UserError("FreeType did not start: " + reason(e));
    }
    ~Library() { FT_Done_FreeType(handle_); }
    Library(const Library&) = delete;
    Library& operator=(const Library&) = delete;
    FT_Library get() const { return handle_; }

private:
    FT_Library handle_ = nullptr;
};

class Face {
public:
    Face(const Library& library, const std::string& path) {
        if (FT_Error e = FT_New_Face(library.get(), path.c_str(), 0, &handle_))
            throw FontFileError(fmt::format("the font '{}' could not be read: {}", path, reason(e)));
    }
    ~Face() { FT_Done_Face(handle_); }
    Face(const Face&) = delete;
    Face& operator=(const Face&) = delete;
    FT_Face get() const { return handle_; }

private:
    FT_Face handle_ = nullptr;
};

// FT_Outline_Decompose's callbacks: each piece as a Bézier segment in em units about the pen.
struct Collector {
    std::vector<OutlineSegment>* out;
    glm::dvec2 pen;
    double em;  // em units per font unit
    glm::dvec2 at{0.0};

    glm::dvec2 place(const FT_Vector* v) const { return pen + em * glm::dvec2(double(v->x), double(v->y)); }
    void add(int degree, std::array<glm::dvec2, 4> points) {
        const bool point = std::all_of(points.begin() + 1, points.begin() + degree + 1,
                                       [&](const glm::dvec2& p) { return p == points[0]; });
        if (!point) out->push_back({degree, points});  // FreeType closes contours with pieces of no length
        at = points[degree];
    }
};

Collector& collector(void* user) { return *static_cast<Collector*>(user); }

int move_to(const FT_Vector* to, void* user) {
    collector(user).at = collector(user).place(to);
    return 0;
}
int line_to(const FT_Vector* to, void* user) {
    Collector& c = collector(user);
    c.add(1, {c.at, c.place(to)});
    return 0;
}
int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
    Collector& c = collector(user);
    c.add(2, {c.at, c.place(control), c.place(to)});
    return 0;
}
int cubic_to(const FT_Vector* control1, const FT_Vector* control2, const FT_Vector* to, void* user) {
    Collector& c = collector(user);
    c.add(3, {c.at, c.place(control1), c.place(control2), c.place(to)});
    return 0;
}

std::string character_name(char32_t c) {
    if (c >= 0x20 && c < 0x7f) return fmt::format("'{}' (U+{:04X})", char(c), std::uint32_t(c));
    return fmt::format("U+{:04X}", std::uint32_t(c));
}

}  // namespace

std::u32string decode_utf8(std::string_view utf8) {
    std::u32string out;
    for (std::size_t i = 0; i < utf8.size();) {
        const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(utf8[k]); };
        const unsigned lead = byte(i);
        const int extra = lead < 0x80 ? 0 : (lead >> 5) == 0x6 ? 1 : (lead >> 4) == 0xe ? 2 : (lead >> 3) == 0x1e ? 3 : -1;
        if (extra < 0 || i + extra >= utf8.size())
            throw UserError(fmt::format("the text is not UTF-8 at byte {}", i));
        char32_t c = extra == 0 ? lead : lead & (0x3fu >> extra);
        for (int k = 1; k <= extra; ++k) {
            if ((byte(i + k) >> 6) != 0x2) throw UserError(fmt::format("the text is not UTF-8 at byte {}", i + k));
            c = (c << 6) | (byte(i + k) & 0x3fu);
        }
        static constexpr char32_t kLeast[] = {0, 0x80, 0x800, 0x10000};  // overlong forms are not UTF-8
        if (c < kLeast[extra] || c > 0x10ffff || (c >= 0xd800 && c <= 0xdfff))
            throw UserError(fmt::format("the text is not UTF-8 at byte {}", i));
        out.push_back(c);
        i += extra + 1;
    }
    return out;
}

TextOutline outline_text(const std::string& font_path, std::string_view utf8, glm::dvec2 offset) {
    const std::u32string text = decode_utf8(utf8);
    Library library;
    Face face(library, font_path);
    FT_Face f = face.get();
    if (!FT_IS_SCALABLE(f) || f->units_per_EM == 0)
        throw FontFileError(fmt::format("the font '{}' has no outlines (a bitmap font)", font_path));

    TextOutline result;
    Collector collect{&result.segments, glm::dvec2(0.0), 1.0 / f->units_per_EM};
    const FT_Outline_Funcs funcs{move_to, line_to, conic_to, cubic_to, 0, 0};
    FT_UInt previous = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const FT_UInt glyph = FT_Get_Char_Index(f, text[i]);
        if (glyph == 0)
            throw UserError(fmt::format("the font '{}' has no glyph for the character {}", font_path,
                                        character_name(text[i])));
        const FT_Int32 load = FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP | FT_LOAD_IGNORE_TRANSFORM;
        if (FT_Error e = FT_Load_Glyph(f, glyph, load))
            throw UserError(fmt::format("the font '{}': the glyph of {} could not be read: {}", font_path,
                                        character_name(text[i]), reason(e)));
        FT_GlyphSlot slot = f->glyph;
        if (slot->format != FT_GLYPH_FORMAT_OUTLINE)
            throw UserError(fmt::format("the font '{}' has no outline for {}", font_path, character_name(text[i])));
        if (i == 0) {
            // POV-Ray puts the first glyph's left edge (its points' least x) at the origin.
            FT_BBox box{};
            if (slot->outline.n_points > 0) FT_Outline_Get_CBox(&slot->outline, &box);
            collect.pen.x = -collect.em * double(box.xMin);
        } else if (FT_HAS_KERNING(f)) {
            FT_Vector kern{};
            if (FT_Get_Kerning(f, previous, glyph, FT_KERNING_UNSCALED, &kern) == 0) collect.pen.x += collect.em * double(kern.x);
        }
        const std::size_t before = result.segments.size();
        if (FT_Error e = FT_Outline_Decompose(&slot->outline, &funcs, &collect))
            throw UserError(fmt::format("the font '{}': the outline of {} could not be read: {}", font_path,
                                        character_name(text[i]), reason(e)));
        if (result.segments.size() > before) ++result.glyphs;
        collect.pen.x += collect.em * double(slot->metrics.horiAdvance);
        collect.pen += offset;
        previous = glyph;
    }
    if (!result.segments.empty()) {
        result.min = result.max = result.segments.front().points[0];
        for (const OutlineSegment& s : result.segments)
            for (int k = 0; k <= s.degree; ++k) {
                result.min = glm::min(result.min, s.points[k]);
                result.max = glm::max(result.max, s.points[k]);
            }
    }
    return result;
}

}  // namespace lancer::font

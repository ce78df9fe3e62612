// Glyph outlines from font files (host/font/text_outline.hpp): closed contours in em units, laid out
// as POV-Ray's text object lays them out, and clear errors for what cannot be drawn.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "font/text_outline.hpp"

namespace lancer::font {
namespace {

const std::string kDejaVu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const std::string kTimesRoman = "/usr/share/fonts/truetype/povray/timrom.ttf";  // POV-Ray's own

// The area the contours enclose by the even-odd rule, when they do not cross: the sum of each
// contour's signed area (Green's theorem, exact for Bézier pieces) taken with its sign, whose total
// is the even-odd area for nested contours of alternating orientation, as fonts draw them.
double signed_area(const TextOutline& o) {
    double twice = 0.0;
    for (const OutlineSegment& s : o.segments) {
        // The integral of x dy - y dx over a Bézier piece, by Gauss-Legendre on its derivative (exact
        // for the degree-5 integrand of a cubic with 3 nodes).
        const double nodes[3] = {0.5 - std::sqrt(0.15), 0.5, 0.5 + std::sqrt(0.15)};
        const double weights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
        for (int k = 0; k < 3; ++k) {
            const double u = nodes[k];
            glm::dvec2 p(0.0), d(0.0);
            if (s.degree == 1) {
                p = s.points[0] + u * (s.points[1] - s.points[0]);
                d = s.points[1] - s.points[0];
            } else if (s.degree == 2) {
                p = (1 - u) * (1 - u) * s.points[0] + 2 * u * (1 - u) * s.points[1] + u * u * s.points[2];
                d = 2.0 * ((1 - u) * (s.points[1] - s.points[0]) + u * (s.points[2] - s.points[1]));
            } else {
                const double v = 1 - u;
                p = v * v * v * s.points[0] + 3 * u * v * v * s.points[1] + 3 * u * u * v * s.points[2] + u * u * u * s.points[3];
                d = 3.0 * (v * v * (s.points[1] - s.points[0]) + 2 * u * v * (s.points[2] - s.points[1]) +
                           u * u * (s.points[3] - s.points[2]));
            }
            twice += weights[k] * (p.x * d.y - p.y * d.x);
        }
    }
    return 0.5 * twice;
}

// Closed: at every point as many pieces end as start (each contour returns to its start).
bool closed(const TextOutline& o) {
    std::map<std::pair<double, double>, int> balance;
    for (const OutlineSegment& s : o.segments) {
        ++balance[{s.points[0].x, s.points[0].y}];
        --balance[{s.points[s.degree].x, s.points[s.degree].y}];
    }
    for (const auto& [point, count] : balance)
        if (count != 0) return false;
    return !o.segments.empty();
}

TEST(TextOutline, AGlyphIsClosedAndSitsOnTheBaselineFromTheOrigin) {
    const TextOutline o = outline_text(kDejaVu, "I", {0.0, 0.0});
    EXPECT_EQ(o.glyphs, 1);
    EXPECT_TRUE(closed(o));
    EXPECT_DOUBLE_EQ(o.min.x, 0.0);  // the first glyph's left edge at the origin, as POV-Ray's
    EXPECT_DOUBLE_EQ(o.min.y, 0.0);  // on the baseline
    EXPECT_GT(o.max.y, 0.6);         // a capital is most of an em tall
    EXPECT_LT(o.max.y, 0.8);
    for (const OutlineSegment& s : o.segments) EXPECT_EQ(s.degree, 1) << "DejaVu's I is a rectangle";
    // A rectangle: its area is its box's.
    EXPECT_NEAR(std::abs(signed_area(o)), (o.max.x - o.min.x) * (o.max.y - o.min.y), 1e-12);
}

TEST(TextOutline, CurvedGlyphsAreQuadraticPiecesAndHolesCountAgainstTheArea) {
    const TextOutline o = outline_text(kDejaVu, "O", {0.0, 0.0});
    EXPECT_TRUE(closed(o));
    int quadratic = 0;
    for (const OutlineSegment& s : o.segments) quadratic += s.degree == 2;
    EXPECT_GT(quadratic, 8);
    // The ring's area: well under its box's ellipse (pi/4 of the box), since the hole is taken out.
    const double box = (o.max.x - o.min.x) * (o.max.y - o.min.y);
    const double ring = std::abs(signed_area(o));
    EXPECT_GT(ring, 0.1 * box);
    EXPECT_LT(ring, 0.5 * box);
}

TEST(TextOutline, EachGlyphFollowsTheAdvanceAndTheOffset) {
    const TextOutline one = outline_text(kDejaVu, "I", {0.0, 0.0});
    const TextOutline two = outline_text(kDejaVu, "II", {0.0, 0.0});
    const TextOutline apart = outline_text(kDejaVu, "II", {0.25, 0.5});
    ASSERT_EQ(two.segments.size(), 2 * one.segments.size());
    const std::size_t n = one.segments.size();
    const glm::dvec2 advance = two.segments[n].points[0] - two.segments[0].points[0];
    EXPECT_GT(advance.x, one.max.x);  // the second I starts past the first one's right edge
    EXPECT_DOUBLE_EQ(advance.y, 0.0);
    const glm::dvec2 moved = apart.segments[n].points[0] - apart.segments[0].points[0];
    EXPECT_NEAR(moved.x, advance.x + 0.25, 1e-12);
    EXPECT_NEAR(moved.y, 0.5, 1e-12);
}

TEST(TextOutline, ASpaceHasNoOutlineButMovesThePen) {
    const TextOutline spaced = outline_text(kDejaVu, "I I", {0.0, 0.0});
    const TextOutline close = outline_text(kDejaVu, "II", {0.0, 0.0});
    EXPECT_EQ(spaced.glyphs, 2);
    EXPECT_GT(spaced.max.x, close.max.x + 0.2);
}

TEST(TextOutline, PovRaysOwnFontsRead) {
    const TextOutline o = outline_text(kTimesRoman, "POV-Ray", {0.0, 0.0});
    EXPECT_EQ(o.glyphs, 7);
    EXPECT_TRUE(closed(o));
    EXPECT_NEAR(o.min.x, 0.0, 1e-12);
    EXPECT_GT(o.max.x, 3.0);  // seven glyphs of about half an em
    EXPECT_LT(o.max.x, 5.0);
}

TEST(TextOutline, ACharacterTheFontLacksIsNamed) {
    try {
        outline_text(kDejaVu, "a\xee\x80\x80", {0.0, 0.0});  // U+E000, private use
        FAIL() << "expected an error";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("no glyph for the character U+E000"), std::string::npos) << e.what();
    }
}

TEST(TextOutline, AFileThatIsNoFontIsRefused) {
    const auto path = std::filesystem::temp_directory_path() / "lancer_text_outline_not_a_font.ttf";
    std::ofstream(path) << "not a font\n";
    try {
        outline_text(path.string(), "a", {0.0, 0.0});
        FAIL() << "expected an error";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("could not be read"), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
}

TEST(TextOutline, Utf8IsDecodedAndMalformedBytesAreRefused) {
    EXPECT_EQ(decode_utf8("a\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80"), std::u32string(U"a\u00e9\u20ac\U0001F600"));
    for (const char* bad : {"\xc3", "\x80", "\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80", "\xe2\x82"})
        EXPECT_THROW(decode_utf8(bad), UserError) << bad;
}

}  // namespace
}  // namespace lancer::font

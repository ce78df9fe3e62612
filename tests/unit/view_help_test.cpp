// The on-screen help: every key it lists is drawn with real glyphs, and docs/viewer.md's key table
// names the same keys.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "view/bitmap_font.hpp"
#include "view/help_panel.hpp"
#include "view/key_bindings.hpp"
#include "view/shown_frame.hpp"
#include "view/status_text.hpp"

namespace lancer::view {
namespace {

std::vector<std::string> split_keys(const std::string& keys) {
    std::vector<std::string> out;
    std::istringstream in(keys);
    for (std::string word; in >> word;)
        if (word != "/") out.push_back(word);
    return out;
}

TEST(ViewHelp, EveryCharacterHasAGlyph) {
    for (const auto& row : key_help())
        for (char c : row.keys + row.action) EXPECT_TRUE(has_glyph(c)) << "'" << c << "' in " << row.action;
}

TEST(ViewHelp, TextIsDrawnInItsColourWithinItsBox) {
    Canvas canvas(40, 12);
    canvas.fill(0x000000ffu);
    draw_text(canvas, 1, 1, "H", 1, 0xff0000ffu);
    int ink = 0;
    for (int y = 0; y < canvas.height; ++y)
        for (int x = 0; x < canvas.width; ++x) {
            const std::uint8_t* p = &canvas.rgba[(std::size_t(y) * canvas.width + x) * 4];
            if (p[0] == 255 && p[1] == 0) {
                ++ink;
                EXPECT_TRUE(x >= 1 && x < 1 + kGlyphWidth && y >= 1 && y < 1 + kGlyphHeight) << x << "," << y;
            }
        }
    EXPECT_EQ(ink, 5 + 5 + 7);  // H: two columns of 7, a bar of 3 between them
    EXPECT_EQ(text_width("HH", 2), (2 * kGlyphAdvance - 1) * 2);
    draw_text(canvas, 35, 8, "WWW", 3, 0xffffffffu);  // clipped, not out of bounds
}

// Counts the pixels of `panel` that are not the veil: its text.
int ink(const HelpPanel& panel) {
    int n = 0;
    for (std::size_t i = 0; i < panel.canvas.rgba.size(); i += 4) n += panel.canvas.rgba[i + 3] == 255;
    return n;
}

TEST(ViewHelp, TheKeyTableWhereItFitsLargerWhereThereIsRoom) {
    HelpPanel big = help_panel(1280, 720), medium = help_panel(320, 180);
    for (const HelpPanel* p : {&big, &medium}) {
        EXPECT_FALSE(p->note);
        ASSERT_EQ(p->lines.size(), key_help().size());
        for (std::size_t k = 0; k < key_help().size(); ++k) {
            EXPECT_EQ(p->lines[k].rfind(key_help()[k].keys, 0), 0u) << p->lines[k];
            EXPECT_NE(p->lines[k].find(key_help()[k].action), std::string::npos) << p->lines[k];
        }
        EXPECT_GT(ink(*p), 0);
    }
    EXPECT_EQ(big.scale, 2);
    EXPECT_EQ(medium.scale, 1);
}

TEST(ViewHelp, ASmallWindowGetsANoteInstead) {
    for (auto [w, h] : {std::pair{160, 90}, std::pair{96, 54}}) {
        HelpPanel p = help_panel(w, h);
        EXPECT_TRUE(p.note) << w << "x" << h;
        std::string text;
        for (const auto& line : p.lines) text += (text.empty() ? "" : " ") + line;
        EXPECT_EQ(text, kHelpTooSmall) << w << "x" << h;
        EXPECT_GT(ink(p), 0);
    }
    HelpPanel tiny = help_panel(20, 10);  // not even the note: nothing at all
    EXPECT_EQ(tiny.canvas.width * tiny.canvas.height, 0);
}

// Whatever the window's size, the panel lies wholly inside it, never touching an edge, and
// every line of its text fits the panel.
TEST(ViewHelp, ThePanelIsAlwaysWhollyInsideTheWindow) {
    for (int w = 1; w <= 700; w += 9)
        for (int h = 1; h <= 400; h += 11) {
            HelpPanel p = help_panel(w, h);
            if (p.canvas.width == 0) continue;
            ASSERT_GT(p.x, 0);
            ASSERT_GT(p.y, 0);
            ASSERT_LT(p.x + p.canvas.width, w) << w << "x" << h;
            ASSERT_LT(p.y + p.canvas.height, h) << w << "x" << h;
            for (const auto& line : p.lines) ASSERT_LT(text_width(line, p.scale), p.canvas.width) << line;
            ASSERT_LT(int(p.lines.size()) * kLineAdvance * p.scale - (kLineAdvance - kGlyphHeight) * p.scale,
                      p.canvas.height);
        }
}

TEST(ViewHelp, TheViewerDocListsEveryKey) {
    std::ifstream in(test::source_path("docs/viewer.md"));
    ASSERT_TRUE(in) << "cannot read docs/viewer.md";
    std::stringstream text;
    text << in.rdbuf();
    std::string doc = text.str();
    auto section = doc.find("## Viewing interactively");
    ASSERT_NE(section, std::string::npos) << "docs/viewer.md has no 'Viewing interactively' section";
    std::string part = doc.substr(section, doc.find("\n## ", section + 1) - section);
    for (const auto& row : key_help())
        for (const std::string& key : split_keys(row.keys))
            EXPECT_NE(part.find("`" + key + "`"), std::string::npos) << "docs/viewer.md does not list `" << key << "`";
}

TEST(ViewStatus, TitleHasPositionFrameTimeAndRaysPerSecond) {
    ShownFrame f;
    f.kind = ShownFrame::Kind::Final;
    f.camera.eye = {1.5, -2, 3.25};
    f.samples = 3;
    f.samples_done = 9;
    f.view_ms = 250;
    f.view_rays = 5e6;
    EXPECT_EQ(window_title("seed.toml", f),
              "lancer view | seed.toml | eye (1.50, -2.00, 3.25) | 9/9 samples in 250 ms | 20.0 Mrays/s");
    f.kind = ShownFrame::Kind::Preview;
    f.preview_divisor = 4;
    f.render_ms = 10;
    f.rays = 1e5;
    EXPECT_EQ(window_title("seed.toml", f),
              "lancer view | seed.toml | eye (1.50, -2.00, 3.25) | preview 1/4 size: 10 ms | 10.0 Mrays/s");
}

}  // namespace
}  // namespace lancer::view

// POV-Ray's text object (host/scene/parse_text.cpp: a font's glyph outlines as one prism) on both
// backends: a letter whose outline is a rectangle against its box, and words (curved outlines,
// holes, POV-Ray's own fonts and offsets, glass, CSG) against the reference.
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "font/text_outline.hpp"
#include "support/test_support.hpp"
#include "support/twin_stage.hpp"

namespace lancer {
namespace {

const char* const kTextTurn = "transform = { scale = 1.6, translate = [-0.9, -0.9, -0.2], rotate = [15, -25, 5] }\n";

void expect_text_backends_agree(const std::string& name, const std::string& stage, const std::string& shape) {
    const Scene scene = test::scene_from_text(stage + shape);
    test::expect_same_picture(name, to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                              to_srgb8(test::render_on(test::Backend::Cpu, scene)));
}

// DejaVu Sans's I is one rectangle: its text is the box of the rectangle's sides, the thickness deep.
TEST(Text, ALetterDrawnAsARectangleIsItsBox) {
    const font::TextOutline outline =
        font::outline_text("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "I", {0.0, 0.0});
    const std::string letter = std::string("type = \"text\"\ntext = \"I\"\nthickness = 0.45\n") + kTextTurn;
    const std::string box = fmt::format("type = \"box\"\nmin = [{:.17g}, {:.17g}, 0]\nmax = [{:.17g}, {:.17g}, 0.45]\n{}",
                                        outline.min.x, outline.min.y, outline.max.x, outline.max.y, kTextTurn);
    const Scene a = test::scene_from_text(std::string(test::kTwinStage) + letter);
    const Scene b = test::scene_from_text(std::string(test::kTwinStage) + box);
    for (test::Backend backend : {test::Backend::Gpu, test::Backend::Cpu})
        test::expect_same_picture(std::string("text-box-") + test::backend_name(backend), to_srgb8(test::render_on(backend, a)),
                                  to_srgb8(test::render_on(backend, b)));
}

const std::string kWordStage = test::twin_stage("[0.6, 1.2, -4.5]", "[0.2, 0.1, 0]", 40);

TEST(Text, AWordRendersAsTheReferenceDoes) {
    expect_text_backends_agree("text-word", kWordStage,
                               "type = \"text\"\ntext = \"lancer\"\nfont = \"DejaVuSans-Bold.ttf\"\nthickness = 0.3\n"
                               "transform = { translate = [-1.2, -0.3, 0], rotate = [10, -20, 0] }\n");
}

TEST(Text, PovRaysFontAndOffsetsRenderAsTheReferenceDoes) {
    expect_text_backends_agree("text-timrom", kWordStage,
                               "type = \"text\"\ntext = \"POV-Ray&\"\nfont = \"timrom.ttf\"\nthickness = 0.5\n"
                               "offset = [0.05, 0.04]\ntransform = { translate = [-1.8, -0.5, 0], rotate = [-15, 25, 0] }\n");
}

TEST(Text, CsgCutsAWord) {
    expect_text_backends_agree("text-difference", kWordStage,
                               "type = \"difference\"\nobjects = [{ type = \"text\", text = \"gab\", thickness = 0.6 }, "
                               "{ type = \"sphere\", center = [0.9, 0.3, 0], radius = 0.45 }]\n"
                               "transform = { scale = 1.5, translate = [-1.2, -0.5, 0], rotate = [20, -35, 0] }\n");
}

TEST(Text, GlassBendsLightAsTheReferenceDoes) {
    expect_text_backends_agree("text-glass", test::kGlassStage,
                               "type = \"text\"\ntext = \"&8\"\nthickness = 0.4\n"
                               "transform = { scale = 1.5, translate = [-0.8, -0.8, -0.2], rotate = [0, 15, 0] }\n");
}

}  // namespace
}  // namespace lancer

// POV-Ray's prism (shaders/shapes/prism.glsl, host/cpu/shapes/prism.cpp) on both backends: a
// square prism against the box it is (on each backend), and the backends against each other
// where no other shape is the same: a square with a hole (the even-odd rule), curved outlines,
// open, CSG both ways, glass, and a star of 3,000 segments (the tree over them on both).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "support/twin_stage.hpp"

namespace lancer {
namespace {

void expect_prism_twins(const std::string& name, const std::string& shape, const std::string& reference) {
    const Scene a = test::scene_from_text(std::string(test::kTwinStage) + shape);
    const Scene b = test::scene_from_text(std::string(test::kTwinStage) + reference);
    for (test::Backend backend : {test::Backend::Gpu, test::Backend::Cpu})
        test::expect_same_picture(name + "-" + test::backend_name(backend), to_srgb8(test::render_on(backend, a)),
                                  to_srgb8(test::render_on(backend, b)));
}

void expect_prism_backends_agree(const std::string& name, const std::string& shape) {
    const Scene scene = test::scene_from_text(std::string(test::kTwinStage) + shape);
    test::expect_same_picture(name, to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                              to_srgb8(test::render_on(test::Backend::Cpu, scene)));
}

const char* const kPrismTurn = "transform = { rotate = [20, 30, 15] }\n";

TEST(Prism, SquareIsTheBox) {
    expect_prism_twins("prism-box", std::string("type = \"prism\"\nheight1 = -0.6\nheight2 = 0.8\npoints = [[-1, -0.7], [0.9, -0.7], [0.9, 1], [-1, 1], [-1, -0.7]]\n") + kPrismTurn,
                       std::string("type = \"box\"\nmin = [-1, -0.6, -0.7]\nmax = [0.9, 0.8, 1]\n") + kPrismTurn);
}

// A conic sweep of a square is a pyramid's frustum: four half-spaces through the apex and a slab.
TEST(Prism, ConicSweepOfASquareIsThePyramid) {
    const char* const turn = "transform = { rotate = [15, 25, 0], translate = [0, -1, 0] }\n";
    expect_prism_twins("prism-pyramid",
                       std::string("type = \"prism\"\nsweep = \"conic\"\nheight1 = 0.6\nheight2 = 1.8\npoints = [[-1, -0.8], [0.9, -0.8], "
                                   "[0.9, 1], [-1, 1], [-1, -0.8]]\n") + turn,
                       std::string("type = \"intersection\"\nobjects = [{ type = \"box\", min = [-2, 0.6, -2], max = [2, 1.8, 2] }, "
                                   "{ type = \"plane\", normal = [1, -0.9, 0] }, { type = \"plane\", normal = [-1, -1, 0] }, "
                                   "{ type = \"plane\", normal = [0, -1, 1] }, { type = \"plane\", normal = [0, -0.8, -1] }]\n") + turn);
}

TEST(Prism, ConicSweepsRenderAsTheReferenceDoes) {
    // To the apex, a curved outline with a hole; and below the apex, upside down.
    expect_prism_backends_agree("prism-conic-apex",
                                "type = \"prism\"\nsweep = \"conic\"\nspline = \"quadratic\"\nheight1 = 0\nheight2 = 1.6\npoints = [[0.6, -0.9], "
                                "[1, 0], [0.6, 0.9], [0, 1], [-0.6, 0.9], [-1, 0], [-0.6, -0.9], [0, -1], [0.6, -0.9], [1, 0], [0.3, -0.3], "
                                "[0.5, 0], [0.3, 0.3], [0, 0.5], [-0.3, 0.3], [-0.5, 0], [-0.3, -0.3], [0, -0.5], [0.3, -0.3], [0.5, 0]]\n"
                                "transform = { rotate = [-20, 0, 10], translate = [0, -1, 0] }\n");
    expect_prism_backends_agree("prism-conic-below",
                                "type = \"prism\"\nsweep = \"conic\"\nspline = \"bezier\"\nheight1 = -0.5\nheight2 = -1.5\npoints = [[0, -0.9], "
                                "[0.9, -0.1], [0.7, 0.9], [0, 0.4], [0, 0.4], [-0.7, 0.9], [-0.9, -0.1], [0, -0.9]]\n"
                                "transform = { rotate = [10, 30, 0], translate = [0, 1, 0] }\n");
}

// A square with a square hole, and a second contour inside the hole: even-odd.
const char* const kPrismHoled =
    "type = \"prism\"\nheight1 = -0.5\nheight2 = 0.5\npoints = [[-1.2, -1.2], [1.2, -1.2], [1.2, 1.2], [-1.2, 1.2], [-1.2, -1.2], "
    "[-0.7, -0.7], [-0.7, 0.7], [0.7, 0.7], [0.7, -0.7], [-0.7, -0.7], [-0.3, -0.3], [0.3, -0.3], [0, 0.35], [-0.3, -0.3]]\n";

TEST(Prism, AHoledSquareRendersAsTheReferenceDoes) {
    expect_prism_backends_agree("prism-holed", std::string(kPrismHoled) + "transform = { rotate = [-25, 10, 0] }\n");
}

TEST(Prism, CurvedOutlinesRenderAsTheReferenceDoes) {
    expect_prism_backends_agree("prism-quadratic",
                                "type = \"prism\"\nspline = \"quadratic\"\nheight1 = -0.4\nheight2 = 0.4\npoints = [[0.6, -0.9], [1, 0], "
                                "[0.6, 0.9], [0, 1], [-0.6, 0.9], [-1, 0], [-0.6, -0.9], [0, -1], [0.6, -0.9], [1, 0], [0.3, -0.3], [0.5, 0], "
                                "[0.3, 0.3], [0, 0.5], [-0.3, 0.3], [-0.5, 0], [-0.3, -0.3], [0, -0.5], [0.3, -0.3], [0.5, 0]]\n" +
                                    std::string(kPrismTurn));
    expect_prism_backends_agree("prism-cubic",
                                "type = \"prism\"\nspline = \"cubic\"\nheight1 = -0.5\nheight2 = 0.5\npoints = [[-0.6, -0.6], [0, -0.8], "
                                "[0.7, -0.5], [0.6, 0.3], [0.1, 0.2], [-0.3, 0.7], [-0.8, 0.1], [-0.6, -0.6], [0, -0.8], [0.7, -0.5]]\n" +
                                    std::string(kPrismTurn));
    expect_prism_backends_agree("prism-bezier",
                                "type = \"prism\"\nspline = \"bezier\"\nheight1 = -0.3\nheight2 = 0.3\npoints = [[0, -0.9], [0.9, -0.1], "
                                "[0.7, 0.9], [0, 0.4], [0, 0.4], [-0.7, 0.9], [-0.9, -0.1], [0, -0.9]]\ntransform = { rotate = [-40, 0, 0] }\n");
}

// Open: no caps, so that rays into it meet the inner walls.
TEST(Prism, OpenShowsItsInside) {
    expect_prism_backends_agree("prism-open", std::string(kPrismHoled) + "open = true\ntransform = { rotate = [-35, 0, 10] }\n");
}

TEST(Prism, CsgCutsItAndIsCutByIt) {
    expect_prism_backends_agree("prism-difference",
                                "type = \"difference\"\nobjects = [{ type = \"prism\", height1 = -0.5, height2 = 0.5, points = [[-1.2, -1.2], "
                                "[1.2, -1.2], [1.2, 1.2], [-1.2, 1.2], [-1.2, -1.2], [-0.7, -0.7], [-0.7, 0.7], [0.7, 0.7], [0.7, -0.7], "
                                "[-0.7, -0.7]] }, { type = \"sphere\", center = [1, 0.5, -1], radius = 0.7 }]\n" +
                                    std::string(kPrismTurn));
    expect_prism_backends_agree("prism-cutter",
                                "type = \"difference\"\nobjects = [{ type = \"box\", min = [-1, -0.5, -1], max = [1, 0.5, 1] }, { type = "
                                "\"prism\", spline = \"bezier\", height1 = 0, height2 = 0.8, points = [[0, -0.9], [0.9, -0.1], [0.7, 0.9], "
                                "[0, 0.4], [0, 0.4], [-0.7, 0.9], [-0.9, -0.1], [0, -0.9]] }]\n" +
                                    std::string(kPrismTurn));
    expect_prism_backends_agree("prism-intersection",
                                "type = \"intersection\"\nobjects = [{ type = \"sphere\", center = [0, 0, 0], radius = 1.1 }, { type = "
                                "\"prism\", height1 = -2, height2 = 2, points = [[-1.2, -1.2], [1.2, -1.2], [1.2, 1.2], [-1.2, 1.2], "
                                "[-1.2, -1.2], [-0.5, -0.5], [-0.5, 0.5], [0.5, 0.5], [0.5, -0.5], [-0.5, -0.5]] }]\n" +
                                    std::string(kPrismTurn));
}

TEST(Prism, GlassBendsLightAsTheReferenceDoes) {
    const Scene scene = test::scene_from_text(std::string(test::kGlassStage) + R"(
        type = "prism"
        spline = "bezier"
        height1 = -0.4
        height2 = 0.4
        points = [[0, -0.9], [0.9, -0.1], [0.7, 0.9], [0, 0.4], [0, 0.4], [-0.7, 0.9], [-0.9, -0.1], [0, -0.9]]
        transform = { rotate = [-30, 20, 0] }
    )");
    test::expect_same_picture("prism-glass", to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                              to_srgb8(test::render_on(test::Backend::Cpu, scene)));
}

// A star of 1,500 points, 3,000 segments: rays find their walls and count the caps' parity
// through the tree over the segments on both backends.
std::string prism_star(int tips) {
    std::string points = "[";
    for (int k = 0; k <= 2 * tips; ++k) {
        const double a = M_PI * (k % (2 * tips)) / tips, r = k % 2 ? 0.93 : 1.0;
        points += "[" + std::to_string(r * std::cos(a)) + ", " + std::to_string(r * std::sin(a)) + "], ";
    }
    return "type = \"prism\"\nheight1 = -0.3\nheight2 = 0.3\npoints = " + points + "]\n";
}

TEST(Prism, AStarOfThousandsOfSegmentsRendersAsTheReferenceDoes) {
    expect_prism_backends_agree("prism-star", prism_star(1500) + "transform = { rotate = [-30, 0, 10], scale = 1.3 }\n");
}

}  // namespace
}  // namespace lancer

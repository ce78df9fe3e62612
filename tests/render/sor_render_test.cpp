// POV-Ray's surface of revolution (shaders/shapes/sor.glsl, host/cpu/shapes/sor.cpp) on both
// backends: against the shapes a sor must be (points on a line are a capped cone's frustum: r^2
// is then the square of a linear r, which POV-Ray's spline reproduces exactly, slopes included),
// and the backends against each other where no other shape is the same (a vase, open, in CSG).
#include <string>

#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "support/twin_stage.hpp"

namespace lancer {
namespace {

void expect_sor_twins(const std::string& name, const std::string& shape, const std::string& reference) {
    const Scene a = test::scene_from_text(std::string(test::kTwinStage) + shape);
    const Scene b = test::scene_from_text(std::string(test::kTwinStage) + reference);
    for (test::Backend backend : {test::Backend::Gpu, test::Backend::Cpu})
        test::expect_same_picture(name + "-" + test::backend_name(backend), to_srgb8(test::render_on(backend, a)),
                                  to_srgb8(test::render_on(backend, b)));
}

void expect_sor_backends_agree(const std::string& name, const std::string& shape) {
    const Scene scene = test::scene_from_text(std::string(test::kTwinStage) + shape);
    test::expect_same_picture(name, to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                              to_srgb8(test::render_on(test::Backend::Cpu, scene)));
}

const char* const kSorTurn = "transform = { rotate = [20, 0, 15] }\n";

TEST(Sor, PointsOfEqualRadiusAreTheCappedCylinder) {
    expect_sor_twins("sor-cylinder", std::string("type = \"sor\"\npoints = [[0.6, -1.3], [0.6, -1], [0.6, 0.2], [0.6, 1], [0.6, 1.3]]\n") + kSorTurn,
                 std::string("type = \"cylinder\"\nbase_point = [0, -1, 0]\ncap_point = [0, 1, 0]\nradius = 0.6\n") + kSorTurn);
}

TEST(Sor, PointsOnALineAreTheCappedCone) {
    // r = 0.5 - 0.2 y through every point: 0.7 at y = -1, 0.3 at y = 1.
    expect_sor_twins("sor-cone",
                 std::string("type = \"sor\"\npoints = [[0.8, -1.5], [0.7, -1], [0.6, -0.5], [0.4, 0.5], [0.3, 1], [0.2, 1.5]]\n") + kSorTurn,
                 std::string("type = \"cone\"\nbase_point = [0, -1, 0]\nbase_radius = 0.7\ncap_point = [0, 1, 0]\ncap_radius = 0.3\n") +
                     kSorTurn);
}

const char* const kSorVase = "type = \"sor\"\npoints = [[0, -1.2], [0.5, -1], [0.8, -0.5], [0.35, 0.3], [0.3, 0.6], [0.55, 1], [0.5, 1.2]]\n";

TEST(Sor, AVaseRendersAsTheReferenceDoes) { expect_sor_backends_agree("sor-vase", std::string(kSorVase) + kSorTurn); }

// Open: no discs, so that rays into its mouth meet the inner wall.
TEST(Sor, OpenShowsItsInside) {
    expect_sor_backends_agree("sor-open", std::string(kSorVase) + "open = true\ntransform = { rotate = [-35, 0, 10] }\n");
}

TEST(Sor, CsgCutsItAndIsCutByIt) {
    expect_sor_backends_agree("sor-difference", "type = \"difference\"\nobjects = [{ " + std::string("type = \"sor\", points = [[0, -1.2], [0.5, -1], [0.8, -0.5], [0.35, 0.3], [0.3, 0.6], [0.55, 1], [0.5, 1.2]]") +
                                                " }, { type = \"box\", min = [-1, 0, -1], max = [0, 1.5, 0] }]\n" + kSorTurn);
    expect_sor_backends_agree("sor-intersection",
                          "type = \"intersection\"\nobjects = [{ type = \"sphere\", center = [0, 0, 0], radius = 0.9 }, { type = "
                          "\"sor\", points = [[0, -1.2], [0.5, -1], [0.8, -0.5], [0.35, 0.3], [0.3, 0.6], [0.55, 1], [0.5, 1.2]] }]\n" +
                              std::string(kSorTurn));
}

TEST(Sor, GlassBendsLightAsTheReferenceDoes) {
    const Scene scene = test::scene_from_text(std::string(test::kGlassStage) + R"(
        type = "sor"
        points = [[0, -1.2], [0.5, -1], [0.8, -0.5], [0.35, 0.3], [0.3, 0.6], [0.55, 1], [0.5, 1.2]]
    )");
    test::expect_same_picture("sor-glass", to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                              to_srgb8(test::render_on(test::Backend::Cpu, scene)));
}

}  // namespace
}  // namespace lancer

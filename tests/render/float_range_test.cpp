// The GPU computes in float, the reference in double. Where float cannot follow (a
// constant beyond float's range, weights below it), the GPU must either draw what the reference
// draws or the scene must be refused at load; never a different picture without a word.
#include <algorithm>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "gpu/packing/scene_packing.hpp"
#include "scene/load_scene.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

const char* kStage = R"(
    [render]
    width = 96
    height = 72
    samples = 2
    [camera]
    eye = [0.3, 0.6, -3]
    look_at = [0, 0, 0]
    fov = 50
    [[light]]
    position = [-3, 4, -5]
    [material.m]
    checker = { colors = [[0.8, 0.5, 0.2], [0.2, 0.3, 0.8]], size = 0.25 }
    [[object]]
    material = "m"
)";

// A bicubic patch over [-1, 1]^2 bulging towards the camera, with every weight `w`.
std::string bulging_patch(const std::string& w) {
    std::string points, weights;
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            double x = -1.0 + 2.0 * i / 3.0, y = -1.0 + 2.0 * j / 3.0;
            double z = (i == 1 || i == 2) && (j == 1 || j == 2) ? -0.8 : 0.0;
            points += fmt::format("{}[{}, {}, {}]", points.empty() ? "" : ", ", x, y, z);
            weights += (weights.empty() ? "" : ", ") + w;
        }
    }
    return fmt::format("type = \"bezier\"\ncontrol_points = [{}]\nweights = [{}]\n", points, weights);
}

// Weights of 1e-50 are a valid rational patch, the same surface as weights 1; in float they
// were all 0 until the packing normalised them.
TEST(FloatRange, TinyRationalWeightsRenderOnTheGpuAsTheReferenceDoes) {
    Scene tiny = test::scene_from_text(std::string(kStage) + bulging_patch("1e-50"));
    Scene unit = test::scene_from_text(std::string(kStage) + bulging_patch("1"));
    Rgb8Image gpu = to_srgb8(test::render_on(test::Backend::Gpu, tiny));
    test::expect_same_picture("tiny-weights-gpu-vs-cpu", gpu, to_srgb8(test::render_on(test::Backend::Cpu, tiny)));
    test::expect_same_picture("tiny-weights-vs-unit-weights", gpu, to_srgb8(test::render_on(test::Backend::Gpu, unit)));
}

// The stage with every length times `scale`: camera, light and the object's place.
std::string scaled_stage(double scale) {
    return fmt::format(R"(
        [render]
        width = 96
        height = 72
        samples = 2
        [camera]
        eye = [{0}, {1}, {2}]
        look_at = [0, 0, 0]
        fov = 50
        [[light]]
        position = [{3}, {4}, {5}]
        [material.m]
        checker = {{ colors = [[0.8, 0.5, 0.2], [0.2, 0.3, 0.8]], size = {6} }}
        [[object]]
        material = "m"
    )", 0.3 * scale, 0.6 * scale, -3 * scale, -3 * scale, 4 * scale, -5 * scale, 0.25 * scale);
}

// Surfaces whose partial derivatives or gradients are far from 1 within lancer's range: their
// squares overflow or underflow float, and the GPU drew them flat and unlit until each was
// scaled by a power of two first (common.glsl, unit_scale).
TEST(FloatRange, NormalsOfHugeAndTinyScalesAreTheReferences) {
    const std::pair<const char*, std::string> cases[] = {
        {"parametric sphere of radius 1e10",
         scaled_stage(1e10) + "type = \"parametric\"\nx = \"R*cos(u)*cos(v)\"\ny = \"R*sin(v)\"\nz = \"R*sin(u)*cos(v)\"\n"
                              "u = [0, \"2*pi\"]\nv = [\"-pi/2\", \"pi/2\"]\nparams = { R = 1e10 }\n"},
        {"Bezier patch 3e10 across", scaled_stage(1.5e10) + bulging_patch("1") + "transform = { scale = 1.5e10 }\n"},
        {"implicit 1e20 (x^2 + y^2 + z^2 - 1)",
         std::string(kStage) + "type = \"implicit\"\nfunction = \"1e20*(x^2 + y^2 + z^2 - 1)\"\n"
                               "box = { min = [-1.1, -1.1, -1.1], max = [1.1, 1.1, 1.1] }\n"},
        {"implicit torus, a quartic times 1e-6",
         std::string(kStage) + "type = \"implicit\"\n"
                               "function = \"1e-6*((x^2 + y^2 + z^2 + 0.8)^2 - 4*(x^2 + z^2))\"\n"
                               "box = { min = [-1.5, -0.5, -1.5], max = [1.5, 0.5, 1.5] }\n"},
        {"implicit 1e-30 (x^2 + y^2 + z^2 - 1)",
         std::string(kStage) + "type = \"implicit\"\nfunction = \"1e-30*(x^2 + y^2 + z^2 - 1)\"\n"
                               "box = { min = [-1.1, -1.1, -1.1], max = [1.1, 1.1, 1.1] }\n"},
    };
    for (const auto& [what, text] : cases) {
        SCOPED_TRACE(what);
        const Scene scene = test::scene_from_text(text);
        test::expect_same_picture(std::string("scaled-normals-") + what, to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                                  to_srgb8(test::render_on(test::Backend::Cpu, scene)));
    }
}

// Equal weights are a polynomial patch, whatever their value: packed with weight 1, so that the
// GPU clips it without the homogeneous coordinate; unequal weights keep it (and their ratios).
TEST(FloatRange, EqualWeightsArePackedAsAPolynomialPatch) {
    for (const char* w : {"1e-50", "1", "3.5"}) {
        gpu::PackedScene packed = gpu::pack_scene(test::scene_from_text(std::string(kStage) + bulging_patch(w)));
        EXPECT_FALSE(packed.features.has_rational_patches) << w;
        for (const gpu::PatchLeaf& leaf : packed.patches)
            for (const gpu::vec4& point : leaf.points) ASSERT_EQ(point.w, 1.0f) << w;
    }
    std::string varied = bulging_patch("1");
    varied.replace(varied.rfind("1]"), 2, "3]");  // the last weight 3: a rational patch
    gpu::PackedScene packed = gpu::pack_scene(test::scene_from_text(std::string(kStage) + varied));
    EXPECT_TRUE(packed.features.has_rational_patches);
    float heaviest = 0.0f;
    for (const gpu::PatchLeaf& leaf : packed.patches)
        for (const gpu::vec4& point : leaf.points) heaviest = std::max(heaviest, point.w);
    EXPECT_GT(heaviest, 1.0f);
}

// "u*1e40/1e40" is u in double and NaN in float: refused, at the constant.
TEST(FloatRange, AConstantBeyondFloatIsRefusedAtItsColumn) {
    const std::string text = std::string(kStage) +
                             "type = \"parametric\"\nx = \"u*1e40/1e40\"\ny = \"v\"\nz = \"0\"\nu = [0, 1]\nv = [0, 1]\n";
    try {
        test::scene_from_text(text);
        FAIL() << "the surface was accepted";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().column, 8);
        EXPECT_NE(std::string(e.what()).find("beyond float's range"), std::string::npos) << e.what();
    }
}

// What float can evaluate is rendered alike by both: a surface with large intermediate
// values (1e30, well within float) and a constant folded in double from out-of-range parts.
TEST(FloatRange, SurfacesWithinFloatRenderAlike) {
    Scene scene = test::scene_from_text(std::string(kStage) + R"toml(
        type = "parametric"
        x = "u*1e30/1e30 + (1e40/1e40 - 1)"
        y = "v"
        z = "0.3*sin(3*u)*cos(2*v)"
        u = [-1, 1]
        v = [-1, 1]
    )toml");
    test::expect_same_picture("float-range-gpu-vs-cpu", to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                              to_srgb8(test::render_on(test::Backend::Cpu, scene)));
}

}  // namespace
}  // namespace lancer

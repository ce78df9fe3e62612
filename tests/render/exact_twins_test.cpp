// Exact surfaces on the GPU against their closed-form or certified twins, from views that stress
// them: edge-on, along the axis, grazing the top of a torus's tube, and the whole scene moved
// 10^6 away from the origin. A twin must match to at least 60 dB with no pixel off by more than
// 10% (25/255 in any channel), at one ray per pixel, where nothing averages an error away: a
// lost grazing hit, a speckle (a lit pixel drawn at its surface's ambient-only colour) or a
// patch seam shows up as such a pixel.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/rational_patches.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

constexpr int kWidth = 320, kHeight = 180;

// A view of the stage: where the eye is, and which way is up.
struct View {
    const char* name;
    glm::dvec3 eye, up;
};

// The objects lie around the origin with their axes along z, over a floor at z = -1.4, lit from
// above and to the side.
std::string stage(const View& v, const std::string& object) {
    return fmt::format(R"toml(
        [render]
        width = {}
        height = {}
        samples = 1
        background = [0.4, 0.5, 0.7]
        [camera]
        eye = [{}, {}, {}]
        look_at = [0, 0, 0]
        up = [{}, {}, {}]
        fov = 40
        [[light]]
        position = [-3, -4, 6]
        [material.floor]
        color = [0.7, 0.7, 0.7]
        [material.m]
        color = [0.8, 0.5, 0.2]
        specular = 0.6
        shininess = 30
        [[object]]
        type = "plane"
        point = [0, 0, -1.4]
        normal = [0, 0, 1]
        material = "floor"
        [[object]]
        material = "m"
        {}
    )toml",
                       kWidth, kHeight, v.eye.x, v.eye.y, v.eye.z, v.up.x, v.up.y, v.up.z, object);
}

// The twin metric above; on failure the images are kept under the test's output directory.
void expect_twin(const std::string& name, const FloatImage& reference, const FloatImage& twin) {
    const Rgb8Image a = to_srgb8(reference), b = to_srgb8(twin);
    const ImageDiff d = compare_images(a, b, 25);
    testing::Test::RecordProperty(name + "_psnr_db", std::to_string(d.psnr_db));
    const long long pixels_over = std::llround(d.fraction_over * a.width * a.height);
    if (d.psnr_db >= 60.0 && pixels_over == 0) return;
    ADD_FAILURE() << name << ": PSNR " << d.psnr_db << " dB, " << pixels_over
                  << " pixels off by more than 10% (largest " << d.max_abs << "/255); images in "
                  << test::save_comparison(name, a, b);
}

const View kSphereViews[] = {
    {"oblique", {2.6, -3.6, 2.4}, {0, 0, 1}},
    {"along_the_axis", {0.0, 0.3, 5.0}, {0, 1, 0}},  // looking down on a pole, where four patches meet
    {"edge_on", {0.0, -5.0, 0.0}, {0, 0, 1}},         // the equator, a seam of the patches, seen edge-on
};

const View kTorusViews[] = {
    {"oblique", {2.2, -3.0, 2.0}, {0, 0, 1}},
    {"along_the_axis", {0.0, 0.0, 4.5}, {0, 1, 0}},
    {"edge_on", {0.0, -4.5, 0.0}, {0, 0, 1}},
    {"grazing_the_tube", {0.0, -4.5, 0.35}, {0, 0, 1}},  // rays skim the top of the tube
};

const char* kParametricSphere = R"toml(
        type = "parametric"
        x = "1.2*cos(v)*cos(u)"
        y = "1.2*cos(v)*sin(u)"
        z = "1.2*sin(v)"
        u = [0, "2*pi"]
        v = ["-pi/2", "pi/2"]
)toml";

const char* kParametricTorus = R"toml(
        type = "parametric"
        x = "(1 + 0.35*cos(v)) * cos(u)"
        y = "(1 + 0.35*cos(v)) * sin(u)"
        z = "0.35*sin(v)"
        u = [0, "2*pi"]
        v = [0, "2*pi"]
)toml";

// The sphere of radius r as 8 rational bicubic patches: two quarter arcs of its profile, each
// swept through four quarter turns.
std::vector<surface::BezierPatch> sphere_patches(double r) {
    std::vector<surface::BezierPatch> out;
    for (int k : {3, 0})
        for (int q = 0; q < 4; ++q) out.push_back(test::revolve(test::quarter_circle({0, 0}, r, k), q, glm::dvec3(0.0)));
    return out;
}

Scene with_patches(const std::string& parametric_text, std::vector<surface::BezierPatch> patches) {
    Scene s = test::scene_from_text(parametric_text);
    s.objects[1].shape = BezierSurface{std::move(patches), 1, ""};
    return s;
}

// Far from the origin, camera and light with them, a twin must match its reference there as it
// does at the origin: the GPU works relative to the camera. (The picture itself may differ from
// the one at the origin by a pixel where a shadow ray grazes an edge: secondary rays start a
// distance from the surface that scales with the distance from the working origin, which is the
// world origin for the first and the eye for the second; scene/camera.hpp.)
const glm::dvec3 kFar(1e6, -1e6, 2e6);

// The twins against their reference, at the origin and moved far from it: the reference on
// `backend`, the twins on the GPU.
void expect_twins_everywhere(const std::string& name, test::Backend backend, const Scene& reference,
                             const std::vector<std::pair<std::string, Scene>>& twins) {
    for (const bool far : {false, true}) {
        auto place = [&](const Scene& s) { return far ? test::moved_scene(s, kFar) : s; };
        const FloatImage expected = test::render_on(backend, place(reference));
        for (const auto& [kind, twin] : twins)
            expect_twin(fmt::format("{}-{}{}", name, kind, far ? "-far" : ""), expected,
                        test::render_on(test::Backend::Gpu, place(twin)));
    }
}

class SphereTwins : public testing::TestWithParam<View> {};

// The parametric sphere and the rational-patch sphere against the analytic sphere, all on the GPU.
TEST_P(SphereTwins, MatchTheAnalyticSphere) {
    const View v = GetParam();
    const Scene analytic = test::scene_from_text(stage(v, "type = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1.2\n"));
    expect_twins_everywhere(fmt::format("sphere-{}", v.name), test::Backend::Gpu, analytic,
                            {{"parametric", test::scene_from_text(stage(v, kParametricSphere))},
                             {"patches", with_patches(stage(v, kParametricSphere), sphere_patches(1.2))}});
}

INSTANTIATE_TEST_SUITE_P(Views, SphereTwins, testing::ValuesIn(kSphereViews),
                         [](const testing::TestParamInfo<View>& info) { return std::string(info.param.name); });

class TorusTwins : public testing::TestWithParam<View> {};

// The parametric torus and the rational-patch torus on the GPU against the CPU reference's
// torus, whose roots are certified in double precision (cpu/shapes/parametric.cpp).
TEST_P(TorusTwins, MatchTheCertifiedTorus) {
    const View v = GetParam();
    const Scene parametric = test::scene_from_text(stage(v, kParametricTorus));
    expect_twins_everywhere(fmt::format("torus-{}", v.name), test::Backend::Cpu, parametric,
                            {{"parametric", parametric},
                             {"patches", with_patches(stage(v, kParametricTorus), test::torus_patches(1.0, 0.35))}});
}

INSTANTIATE_TEST_SUITE_P(Views, TorusTwins, testing::ValuesIn(kTorusViews),
                         [](const testing::TestParamInfo<View>& info) { return std::string(info.param.name); });

// The torus shape (an exact quartic: shaders/shapes/torus.glsl, cpu/shapes/torus.cpp) and the
// same quartic as an implicit surface, on both backends: the CPU's torus against the CPU's
// implicit surface (two certified solvers) and the GPU's torus against the CPU's, to the twins'
// bar above; the GPU's implicit surface against the CPU's torus to a looser one, 50 dB and at
// most 8 pixels over 10%: its interval search loses or gains a few silhouette pixels against
// either reference (4 in the oblique view, 54 dB; the GPU's torus none, 60+ dB).
const char* kTorusShape = R"toml(
        type = "torus"
        axis = [0, 0, 1]
        major_radius = 1
        minor_radius = 0.35
)toml";

const char* kImplicitTorus = R"toml(
        type = "implicit"
        function = "(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + y^2)"
        params = { R = 1, r = 0.35 }
        box = { min = [-1.4, -1.4, -0.4], max = [1.4, 1.4, 0.4] }
)toml";

class TorusShapeTwins : public testing::TestWithParam<View> {};

TEST_P(TorusShapeTwins, MatchesTheImplicitQuarticOnBothBackends) {
    const View v = GetParam();
    const Scene shape = test::scene_from_text(stage(v, kTorusShape));
    const Scene implicit = test::scene_from_text(stage(v, kImplicitTorus));
    for (const bool far : {false, true}) {
        auto place = [&](const Scene& s) { return far ? test::moved_scene(s, kFar) : s; };
        const std::string name = fmt::format("torus-shape-{}{}", v.name, far ? "-far" : "");
        const FloatImage cpu = test::render_on(test::Backend::Cpu, place(shape));
        expect_twin(name + "-cpu-implicit", cpu, test::render_on(test::Backend::Cpu, place(implicit)));
        expect_twin(name + "-gpu", cpu, test::render_on(test::Backend::Gpu, place(shape)));
        const Rgb8Image a = to_srgb8(cpu), b = to_srgb8(test::render_on(test::Backend::Gpu, place(implicit)));
        const ImageDiff d = compare_images(a, b, 25);
        const long long over = std::llround(d.fraction_over * a.width * a.height);
        testing::Test::RecordProperty(name + "-gpu-implicit_psnr_db", std::to_string(d.psnr_db));
        EXPECT_TRUE(d.psnr_db >= 50.0 && over <= 8) << name << "-gpu-implicit: PSNR " << d.psnr_db << " dB, " << over
                                                    << " pixels off by more than 10%; images in "
                                                    << test::save_comparison(name + "-gpu-implicit", a, b);
    }
}

INSTANTIATE_TEST_SUITE_P(Views, TorusShapeTwins, testing::ValuesIn(kTorusViews),
                         [](const testing::TestParamInfo<View>& info) { return std::string(info.param.name); });

// A flat Bezier patch with evenly spaced control points is the square it spans: against the
// rectangle from views that graze its plane. The eye is 1 above a square 20,000 across and looks
// at the point of it where the central ray meets the plane at the elevation angle (rows below
// meet it more steeply, rows above only far away, up to the square's far edge). The material is
// plain: the picture compares where each shape is hit, and how it is lit. (A checkerboard would
// compare float's rounding instead: the patch's hit point is computed from points thousands of
// units apart, so a hit 60 units away at 1 degree can lie 0.05 off the rectangle's, and a row of
// pixels whose hits lie that close to a line of the checker then flips colour.)
class FlatPatchTwin : public testing::TestWithParam<double> {};

TEST_P(FlatPatchTwin, IsTheRectangleFromAGrazingView) {
    const double elevation = GetParam() * test::kDegree;
    const std::string common = fmt::format(R"toml(
        [render]
        width = {}
        height = {}
        samples = 1
        background = [0.4, 0.5, 0.7]
        [camera]
        eye = [0, 1, 0]
        look_at = [30, 0, {}]
        fov = 30
        [[light]]
        position = [-3000, 6000, 3000]
        [material.board]
        color = [0.9, 0.85, 0.7]
        specular = 0.5
        [[object]]
        material = "board"
    )toml",
                                           kWidth, kHeight, 1.0 / std::tan(elevation));
    std::string points;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            points += (points.empty() ? "" : ", ") + fmt::format("[{}, 0, {}]", -10000.0 + 20000.0 * i / 3.0, 20000.0 * j / 3.0);
    const Scene patch = test::scene_from_text(common + "type = \"bezier\"\ncontrol_points = [" + points + "]\n");
    const Scene rect = test::scene_from_text(
        common + "type = \"rectangle\"\ncorner = [-10000, 0, 0]\nedge_u = [20000, 0, 0]\nedge_v = [0, 0, 20000]\n");
    for (const bool far : {false, true}) {
        auto place = [&](const Scene& s) { return far ? test::moved_scene(s, kFar) : s; };
        const FloatImage reference = test::render_on(test::Backend::Gpu, place(rect));
        int covered = 0;
        for (const glm::vec4& p : reference.pixels) covered += glm::abs(p.x - 0.4f) > 0.01f;
        EXPECT_GT(covered, kWidth * kHeight / 4) << "the square must fill part of the view";
        expect_twin(fmt::format("flat-patch-{}deg{}", GetParam(), far ? "-far" : ""), reference,
                    test::render_on(test::Backend::Gpu, place(patch)));
    }
}

INSTANTIATE_TEST_SUITE_P(Elevations, FlatPatchTwin, testing::Values(1.0, 0.1, 0.01, 0.004),
                         [](const testing::TestParamInfo<double>& info) {
                             std::string name = fmt::format("{}deg", info.param);
                             for (char& c : name) c = c == '.' ? '_' : c;
                             return name;
                         });

// No speckles on the shipped exact surfaces: each scene's parametric and patch objects alone (so
// that every pixel they cover shows them), at one ray per pixel; where the CPU reference draws a
// pixel of the surface, the GPU draws none darker by more than 10% (a speckle: a lit point drawn
// at its ambient-only colour, as when a ray takes the farther of two nearby roots and its normal
// turns away from the light). The seed-based intersector left 2 on the torus at this size.
class NoSpeckles : public testing::TestWithParam<std::string> {};

TEST_P(NoSpeckles, OnTheShippedExactSurfaces) {
    Scene scene = test::shipped_scene(GetParam(), 240, 135, 1);
    std::erase_if(scene.objects, [](const Object& o) {
        return !std::holds_alternative<ParametricObject>(o.shape) && !std::holds_alternative<BezierSurface>(o.shape);
    });
    ASSERT_FALSE(scene.objects.empty());
    const Rgb8Image gpu = to_srgb8(test::render_on(test::Backend::Gpu, scene));
    const Rgb8Image cpu = to_srgb8(test::render_on(test::Backend::Cpu, scene));
    Scene empty = scene;
    empty.objects.clear();
    const Rgb8Image background = to_srgb8(test::render_on(test::Backend::Cpu, empty));
    auto luminance = [](const std::uint8_t* c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; };
    int surface = 0, speckles = 0;
    for (int y = 0; y < cpu.height; ++y) {
        for (int x = 0; x < cpu.width; ++x) {
            if (std::equal(cpu.at(x, y), cpu.at(x, y) + 3, background.at(x, y))) continue;
            ++surface;
            if (luminance(gpu.at(x, y)) < luminance(cpu.at(x, y)) - 25.5) ++speckles;
        }
    }
    EXPECT_GT(surface, 500);
    EXPECT_EQ(speckles, 0) << "of " << surface << " pixels of the surface";
}

INSTANTIATE_TEST_SUITE_P(Scenes, NoSpeckles, testing::Values("torus", "klein", "dini", "enneper", "mobius", "teapot"),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace lancer

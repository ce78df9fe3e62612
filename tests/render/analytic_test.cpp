// Scenes whose pixels are known without a renderer: each backend is checked against the Phong
// formula evaluated here by hand, so two backends sharing one bug cannot pass.
#include <cmath>
#include <memory>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/camera.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// GPU arithmetic is float: allow a few ulps of the [0, 1] range.

using test::Backend;


class Analytic : public testing::TestWithParam<Backend> {};

// A unit sphere seen head-on, one light above-front: the centre pixel's colour is
// ka*C*Ia + kd*C*I*(N.L) + ks*I*(R.L)^ns with N = R = (0,0,-1) and L toward the light.
TEST_P(Analytic, LitSphereCentrePixelIsThePhongFormula) {
    Scene s = test::scene_from_text(R"(
        [render]
        width = 9
        height = 9
        samples = 1
        [camera]
        eye = [0, 0, -5]
        look_at = [0, 0, 0]
        fov = 20
        [ambient]
        color = [0.5, 0.6, 0.7]
        [[light]]
        position = [0, 5, -5]
        color = [0.9, 0.8, 0.7]
        [material.m]
        color = [0.8, 0.4, 0.2]
        ambient = 0.2
        diffuse = 0.6
        specular = 0.5
        shininess = 7
        [[object]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
        material = "m"
    )");
    FloatImage img = test::render_on(GetParam(), s);
    glm::dvec3 C(0.8, 0.4, 0.2), Ia(0.5, 0.6, 0.7), I(0.9, 0.8, 0.7);
    double n_dot_l = 4.0 / std::sqrt(41.0);  // hit (0,0,-1), light (0,5,-5): L = (0,5,-4)/sqrt(41)
    glm::dvec3 expected = 0.2 * C * Ia + 0.6 * C * I * n_dot_l + 0.5 * I * std::pow(n_dot_l, 7.0);
    glm::vec4 got = img.at(4, 4);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], test::kBackendTolerance) << "channel " << c;
    EXPECT_EQ(got.a, 2.0f);  // one camera ray + one shadow ray
}

// The floor point straight below a sphere, with the only light straight above, is in shadow:
// exactly the ambient term, nothing more.
TEST_P(Analytic, PointInShadowGetsExactlyTheAmbientTerm) {
    Scene s = test::scene_from_text(R"(
        [render]
        width = 9
        height = 9
        samples = 1
        [camera]
        eye = [0, 5, -5]
        look_at = [0, 0, 0]
        fov = 10
        [ambient]
        color = [0.9, 0.9, 0.9]
        [[light]]
        position = [0, 10, 0]
        [material.floor]
        color = [0.5, 0.7, 0.9]
        ambient = 0.3
        [[object]]
        type = "plane"
        normal = [0, 1, 0]
        material = "floor"
        [[object]]
        type = "sphere"
        center = [0, 2, 0]
        radius = 1
    )");
    FloatImage img = test::render_on(GetParam(), s);
    glm::vec4 got = img.at(4, 4);
    EXPECT_NEAR(got.r, 0.3 * 0.5 * 0.9, test::kBackendTolerance);
    EXPECT_NEAR(got.g, 0.3 * 0.7 * 0.9, test::kBackendTolerance);
    EXPECT_NEAR(got.b, 0.3 * 0.9 * 0.9, test::kBackendTolerance);
}

// An unoccluded, slightly tilted floor seen at grazing angles from far away (large coordinates,
// where naive offsets produce shadow acne): every pixel equals its unshadowed Phong value.
TEST_P(Analytic, UnoccludedFloorHasNoDarkPixels) {
    Scene s = test::scene_from_text(R"(
        [render]
        width = 64
        height = 48
        samples = 1
        [camera]
        eye = [300, 2, -400]
        look_at = [320, 0, -300]
        fov = 40
        [[light]]
        position = [340, 50, -200]
        color = [0.8, 0.8, 0.8]
        [material.floor]
        color = [0.6, 0.6, 0.6]
        ambient = 0.1
        diffuse = 0.7
        [[object]]
        type = "plane"
        point = [3.3, -0.7, 2.1]
        normal = [0.02, 1, 0.01]
        material = "floor"
    )");
    FloatImage img = test::render_on(GetParam(), s);
    const Plane& plane = std::get<Plane>(s.objects[0].shape);
    CameraBasis cam = make_camera_basis(s.camera, s.render.width, s.render.height);
    int floor_pixels = 0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            glm::dvec3 d = glm::normalize(camera_ray_direction(cam, x + 0.5, y + 0.5, img.width, img.height));
            double denom = glm::dot(d, plane.normal);
            if (denom >= -1e-3) continue;  // sky, or too close to the horizon to be sure which
            glm::dvec3 p = cam.eye + (glm::dot(plane.point - cam.eye, plane.normal) / denom) * d;
            double n_dot_l = glm::dot(glm::normalize(s.lights[0].position - p), plane.normal);
            double expected = 0.1 * 0.6 + 0.7 * 0.6 * 0.8 * std::max(0.0, n_dot_l);
            // Relative tolerance: float hit points far from the origin are off by ~1e-5 units.
            EXPECT_NEAR(img.at(x, y).g, expected, 1e-4) << "pixel " << x << "," << y;
            ++floor_pixels;
        }
    }
    EXPECT_GT(floor_pixels, img.width * img.height / 3);
}

// Nothing hit: the background, and exactly one ray per sample.
TEST_P(Analytic, EmptySceneIsBackground) {
    Scene s = test::scene_from_text(R"(
        [render]
        width = 8
        height = 4
        samples = 3
        background = [0.25, 0.5, 0.75]
        [camera]
        eye = [0, 0, -5]
        look_at = [0, 0, 0]
    )");
    FloatImage img = test::render_on(GetParam(), s);
    for (const auto& p : img.pixels) {
        EXPECT_FLOAT_EQ(p.r, 0.25f);
        EXPECT_FLOAT_EQ(p.b, 0.75f);
        EXPECT_EQ(p.a, 9.0f);
    }
}

// A perfect mirror facing a red wall shows the wall's colour; with max_depth = 0 the reflected
// ray is not traced and contributes black.
TEST_P(Analytic, MirrorShowsWhatItFacesUpToMaxDepth) {
    std::string text = R"(
        [render]
        width = 5
        height = 5
        samples = 1
        max_depth = DEPTH
        [camera]
        eye = [0, 0, -5]
        look_at = [0, 0, 0]
        fov = 5
        [ambient]
        color = [1, 1, 1]
        [material.mirror]
        reflection = 1
        [material.wall]
        color = [1, 0, 0]
        ambient = 1
        diffuse = 0
        [[object]]
        type = "plane"
        point = [0, 0, 1]
        normal = [0, 0, -1]
        material = "mirror"
        [[object]]
        type = "rectangle"
        corner = [-50, -50, -10]
        edge_u = [100, 0, 0]
        edge_v = [0, 100, 0]
        material = "wall"
    )";
    auto with_depth = [&](int depth) {
        std::string t = text;
        t.replace(t.find("DEPTH"), 5, std::to_string(depth));
        return test::scene_from_text(t);
    };
    glm::vec4 reflected = test::render_on(GetParam(), with_depth(1)).at(2, 2);
    EXPECT_NEAR(reflected.r, 1.0f, test::kBackendTolerance);
    EXPECT_NEAR(reflected.g, 0.0f, test::kBackendTolerance);
    glm::vec4 cut = test::render_on(GetParam(), with_depth(0)).at(2, 2);
    EXPECT_NEAR(cut.r, 0.0f, test::kBackendTolerance);
}

INSTANTIATE_TEST_SUITE_P(Backends, Analytic, testing::Values(Backend::Gpu, Backend::Cpu),
                         [](const auto& info) { return test::backend_name(info.param); });

}  // namespace
}  // namespace lancer

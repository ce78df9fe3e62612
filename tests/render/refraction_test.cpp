// Refraction on both backends against optics worked out by hand: the lateral shift of a ray
// through a glass slab, Fresnel reflectance at normal incidence, total internal reflection,
// Beer-Lambert absorption, nested media (glass holding a liquid) and shadows through glass.
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/camera.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

using test::Backend;


class Refraction : public testing::TestWithParam<Backend> {
protected:
    FloatImage render(const std::string& toml) { return test::render_on(GetParam(), test::scene_from_text(toml)); }
};

// The unpolarised Fresnel reflectance, written out here from the textbook formulas.
double reflectance(double theta_i, double n1, double n2) {
    double sin_t = n1 * std::sin(theta_i) / n2;
    if (sin_t >= 1.0) return 1.0;
    double ci = std::cos(theta_i), ct = std::sqrt(1.0 - sin_t * sin_t);
    double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
    double rp = (n1 * ct - n2 * ci) / (n1 * ct + n2 * ci);
    return (rs * rs + rp * rp) / 2.0;
}

// A scene lit by ambient light alone, through a camera at `eye` looking at `look_at`: `white`
// (ambient 1) shows as 1; `glass` (index `ior`) and `liquid` (1.33) are clear and dark
// themselves. `rest` adds objects (and materials).
struct View {
    int width = 3, height = 3;
    dvec3 eye{0, 0, -4}, look_at{0, 0, 0};
    double fov = 10;
    int max_depth = 6;
};

std::string ambient_scene(const View& v, const std::string& rest, double ior = 1.5) {
    return fmt::format(R"(
        [render]
        width = {}
        height = {}
        samples = 1
        max_depth = {}
        [camera]
        eye = [{}, {}, {}]
        look_at = [{}, {}, {}]
        fov = {}
        [ambient]
        color = [1, 1, 1]
        [material.white]
        ambient = 1
        diffuse = 0
        [material.glass]
        transmission = 1
        ior = {}
        ambient = 0
        diffuse = 0
        [material.liquid]
        transmission = 1
        ior = 1.33
        ambient = 0
        diffuse = 0
    )",
                       v.width, v.height, v.max_depth, v.eye.x, v.eye.y, v.eye.z, v.look_at.x, v.look_at.y, v.look_at.z, v.fov,
                       ior) +
           rest;
}

// An [[object]] table: a rectangle (corner, edge_u, edge_v) or a box (min, max).
std::string rectangle(const std::string& material, dvec3 c, dvec3 u, dvec3 v) {
    return fmt::format("[[object]]\ntype = \"rectangle\"\ncorner = [{}, {}, {}]\nedge_u = [{}, {}, {}]\n"
                       "edge_v = [{}, {}, {}]\nmaterial = \"{}\"\n",
                       c.x, c.y, c.z, u.x, u.y, u.z, v.x, v.y, v.z, material);
}

std::string box(const std::string& material, dvec3 lo, dvec3 hi) {
    return fmt::format("[[object]]\ntype = \"box\"\nmin = [{}, {}, {}]\nmax = [{}, {}, {}]\nmaterial = \"{}\"\n",
                       lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, material);
}

// A camera at the origin looking along the xz-plane at `deg` degrees from +z, 401 columns wide
// and a few degrees across; the middle row's rays lie in the xz-plane. Behind everything a white
// wall at z = wall_z covers x >= edge_x; the rest is black.
std::string edge_scene(double deg, double wall_z, double edge_x, const std::string& extra) {
    View v{401, 3, {0, 0, 0}, {10 * std::sin(deg * test::kDegree), 0, 10 * std::cos(deg * test::kDegree)}, 0.1};
    return ambient_scene(v, rectangle("white", {edge_x, -50, wall_z}, {50, 0, 0}, {0, 100, 0}) + extra);
}

// The angle from +z of the ray through column c of the middle row of edge_scene's camera.
double column_angle(const Scene& scene, int c) {
    CameraBasis cam = make_camera_basis(scene.camera, scene.render.width, scene.render.height);
    dvec3 d = camera_ray_direction(cam, c + 0.5, 1.5, scene.render.width, scene.render.height);
    return std::atan2(d.x, d.z);
}

// The first column of the middle row brighter than half, or -1.
int first_bright_column(const FloatImage& img) {
    for (int x = 0; x < img.width; ++x)
        if (img.at(x, 1).g > 0.5f) return x;
    return -1;
}

// The first column whose ray lands at x >= edge_x, given where a ray at angle theta lands.
template <typename Landing>
int predicted_column(const Scene& scene, double edge_x, Landing landing) {
    for (int c = 0; c < scene.render.width; ++c)
        if (landing(column_angle(scene, c)) >= edge_x) return c;
    return -1;
}

const std::string kSlab = box("glass", {-50, -50, 2}, {50, 50, 3});

// A slab of thickness t shifts a ray sideways by d = t sin(theta - theta') / cos(theta'), so
// the wall behind it is seen d / cos(theta) further along x than without the slab.
TEST_P(Refraction, SlabDisplacesTheRayByTheTextbookAmount) {
    const double t = 1.0, n = 1.5, wall = 6.0;
    const double edge = wall * std::tan(40 * test::kDegree);  // without the slab: the centre column
    Scene plain = test::scene_from_text(edge_scene(40, wall, edge, ""));
    auto straight = [&](double theta) { return wall * std::tan(theta); };
    auto through_slab = [&](double theta) {
        double theta_t = std::asin(std::sin(theta) / n);
        double d = t * std::sin(theta - theta_t) / std::cos(theta_t);
        return straight(theta) - d / std::cos(theta);
    };
    int expected_plain = predicted_column(plain, edge, straight);
    int expected_slab = predicted_column(plain, edge, through_slab);
    ASSERT_EQ(expected_plain, 200);
    ASSERT_GT(expected_slab - expected_plain, 30) << "the shift must be large enough to measure";

    int got_plain = first_bright_column(render(edge_scene(40, wall, edge, "")));
    int got_slab = first_bright_column(render(edge_scene(40, wall, edge, kSlab)));
    EXPECT_NEAR(got_plain, expected_plain, 1);
    EXPECT_NEAR(got_slab, expected_slab, 1);
}

// Glass (1.5) from z = 2 to 3 and a liquid (1.33) from z = 2.5 to 5, overlapping the glass as
// the documentation tells users to model a filled glass: at z = 2.5 the ray goes from glass into
// liquid and bends by n_glass / n_liquid; the glass's back face at z = 3 lies inside the liquid
// and does not show.
TEST_P(Refraction, NestedMediaBendByTheRatioOfTheirIndices) {
    const double wall = 7.0, ng = 1.5, nl = 1.33;
    auto landing = [&](double theta, bool right_model) {
        double theta_g = std::asin(std::sin(theta) / ng);
        double theta_l = std::asin((right_model ? std::sin(theta) : std::sin(theta_g)) / nl);
        return 2.0 * std::tan(theta) + 0.5 * std::tan(theta_g) + 2.5 * std::tan(theta_l) + 2.0 * std::tan(theta);
    };
    const double edge = landing(40 * test::kDegree, true);
    const std::string objects = kSlab + box("liquid", {-50, -50, 2.5}, {50, 50, 5});
    Scene scene = test::scene_from_text(edge_scene(40, wall, edge, objects));
    int expected = predicted_column(scene, edge, [&](double th) { return landing(th, true); });
    int wrong = predicted_column(scene, edge, [&](double th) { return landing(th, false); });
    ASSERT_EQ(expected, 200);
    ASSERT_GT(std::abs(wrong - expected), 10) << "air-to-liquid bending must land elsewhere";
    EXPECT_NEAR(first_bright_column(render(edge_scene(40, wall, edge, objects))), expected, 1);
}

// Head-on at a glass half-space (a plane) with a white wall behind the camera and black beyond:
// the pixel is the reflectance ((n1 - n2) / (n1 + n2))^2 alone.
TEST_P(Refraction, NormalIncidenceReflectsTheTextbookFraction) {
    for (double n : {1.5, 2.4}) {
        std::string half_space = "[[object]]\ntype = \"plane\"\npoint = [0, 0, 2]\nnormal = [0, 0, -1]\nmaterial = \"glass\"\n";
        FloatImage img = render(ambient_scene(View{}, half_space + rectangle("white", {-50, -50, -5}, {100, 0, 0}, {0, 100, 0}), n));
        double r = std::pow((1.0 - n) / (1.0 + n), 2.0);
        EXPECT_NEAR(img.at(1, 1).r, r, test::kBackendTolerance) << "ior " << n;
    }
}

// Head-on through a slab at a white wall: (1 - R)^2 passes straight through, plus the light
// reflected once inside at each face, R^2 (1 - R)^2; the next round (R^4) is below the cut-off.
TEST_P(Refraction, SlabTransmitsWhatBothFacesLetThrough) {
    FloatImage img = render(ambient_scene(View{}, box("glass", {-50, -50, 1}, {50, 50, 2}) +
                                                      rectangle("white", {-50, -50, 5}, {100, 0, 0}, {0, 100, 0})));
    double r = 0.04;
    EXPECT_NEAR(img.at(1, 1).g, (1 - r) * (1 - r) * (1 + r * r), test::kBackendTolerance);
}

// A ray enters the top of a glass cube at 60 degrees and meets a side face at 90 - theta'. With
// ior 1.2 that is inside the critical angle and the ray reaches the white wall beyond; with 1.5
// it is beyond (54.7 > 41.8 degrees): the ray is reflected down, and nothing reaches the wall.
// max_depth = 2 stops the tree at what the side face sends on (the wall, or the cube's bottom).
TEST_P(Refraction, TotalInternalReflectionBeyondTheCriticalAngle) {
    for (double n : {1.2, 1.5}) {
        View v{3, 3, {0.5 - 10 * std::sin(60 * test::kDegree), 6, 0}, {0.5, 1, 0}, 1, 2};
        FloatImage img = render(ambient_scene(v, box("glass", {-1, -1, -1}, {1, 1, 1}) +
                                                     rectangle("white", {3, -50, -50}, {0, 50.8, 0}, {0, 0, 100}), n));
        double theta_t = std::asin(std::sin(60 * test::kDegree) / n);
        double at_side = 90 * test::kDegree - theta_t;
        bool total = n * std::sin(at_side) > 1.0;
        ASSERT_EQ(total, n == 1.5);
        double expected = total ? 0.0 : (1 - reflectance(60 * test::kDegree, 1.0, n)) * (1 - reflectance(at_side, n, 1.0));
        EXPECT_NEAR(img.at(1, 1).r, expected, test::kBackendTolerance) << "ior " << n;
        if (!total) {
            EXPECT_GT(expected, 0.8);
        }
    }
}

// Beer-Lambert: with ior 1 nothing bends or reflects, and a slab of thickness 0.7 leaves
// exp(-a * path) of the wall's white, the path being 0.7 / cos(theta) at angle theta.
TEST_P(Refraction, AbsorptionFollowsBeerLambert) {
    const dvec3 a(0.5, 1.0, 2.0);
    for (double deg : {0.0, 50.0}) {
        View v{3, 3, {0, 0, 0}, {10 * std::sin(deg * test::kDegree), 0, 10 * std::cos(deg * test::kDegree)}, 1};
        const char* tinted = "[material.tinted]\ntransmission = 1\nabsorption = [0.5, 1, 2]\nambient = 0\ndiffuse = 0\n";
        FloatImage img = render(ambient_scene(v, std::string(tinted) + box("tinted", {-50, -50, 1}, {50, 50, 1.7}) +
                                                     rectangle("white", {-50, -50, 5}, {100, 0, 0}, {0, 100, 0})));
        double path = 0.7 / std::cos(deg * test::kDegree);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.at(1, 1)[c], std::exp(-a[c] * path), test::kBackendTolerance) << deg << " deg, channel " << c;
    }
}

// The floor under a floating glass block, lit from straight above: the shadow ray crosses two
// faces, each passing (1 - k_r) T, and 1 unit of glass absorbing exp(-a). No refraction, no
// Fresnel on shadow rays (the documented approximation).
TEST_P(Refraction, ShadowThroughGlassIsTintedByItsTransmission) {
    FloatImage img = render(R"(
        [render]
        width = 3
        height = 3
        samples = 1
        [camera]
        eye = [0, 0.3, -5]
        look_at = [0, 0, 0]
        fov = 2
        [ambient]
        color = [0.5, 0.5, 0.5]
        [[light]]
        position = [0, 10, 0]
        color = [0.9, 0.9, 0.9]
        [material.floor]
        color = [0.8, 0.7, 0.6]
        ambient = 0.2
        diffuse = 0.7
        [material.glass]
        transmission = [1, 0.6, 0.3]
        absorption = [0, 0.2, 0.5]
        reflection = 0.2
        ior = 1.5
        [[object]]
        type = "plane"
        normal = [0, 1, 0]
        material = "floor"
        [[object]]
        type = "box"
        min = [-0.5, 1, -0.5]
        max = [0.5, 2, 0.5]
        material = "glass"
    )");
    const dvec3 C(0.8, 0.7, 0.6), T(1, 0.6, 0.3), a(0, 0.2, 0.5);
    for (int c = 0; c < 3; ++c) {
        double through = std::pow(0.8 * T[c], 2.0) * std::exp(-a[c]);
        double expected = 0.2 * C[c] * 0.5 + 0.7 * C[c] * 0.9 * through;
        EXPECT_NEAR(img.at(1, 1)[c], expected, test::kBackendTolerance) << "channel " << c;
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, Refraction, testing::Values(Backend::Gpu, Backend::Cpu),
                         [](const auto& info) { return test::backend_name(info.param); });

}  // namespace
}  // namespace lancer

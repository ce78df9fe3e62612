// Spot lights, inverse-square fall-off, area lights' soft shadows and the Blinn highlight on both
// backends, against values worked out here from the formulas of docs/scene-format.md.
#include <algorithm>
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


class LightTypes : public testing::TestWithParam<Backend> {
protected:
    FloatImage render(const Scene& scene) { return test::render_on(GetParam(), scene); }
};

// Where the ray through pixel centre (x, y) meets the floor y = 0.
dvec3 floor_point(const Scene& s, int x, int y) {
    CameraBasis cam = make_camera_basis(s.camera, s.render.width, s.render.height);
    dvec3 d = glm::normalize(camera_ray_direction(cam, x + 0.5, y + 0.5, s.render.width, s.render.height));
    return cam.eye - (cam.eye.y / d.y) * d;
}

// A white floor (diffuse 1, no ambient) seen from straight above, x across the image.
std::string floor_scene(const std::string& lights_and_objects) {
    return R"(
        [render]
        width = 201
        height = 1
        samples = 1
        [camera]
        eye = [0, 10, 0]
        look_at = [0, 0, 0]
        up = [0, 0, 1]
        fov = 0.2
        [material.floor]
        ambient = 0
        diffuse = 1
        [[object]]
        type = "plane"
        normal = [0, 1, 0]
        material = "floor"
    )" + lights_and_objects;
}

// POV-Ray's spot: full within inner_angle, nothing beyond outer_angle, 3t^2 - 2t^3 between.
TEST_P(LightTypes, SpotLightIsFullInsideItsConeAndDarkOutside) {
    Scene s = test::scene_from_text(floor_scene(R"(
        [[light]]
        type = "spot"
        position = [0, 4, 0]
        point_at = [0, 0, 0]
        inner_angle = 10
        outer_angle = 14
    )"));
    FloatImage img = render(s);
    int full = 0, dark = 0, edge = 0;
    for (int x = 0; x < img.width; ++x) {
        dvec3 p = floor_point(s, x, 0);
        dvec3 to_light = dvec3(0, 4, 0) - p;
        double angle = std::acos(4.0 / glm::length(to_light)) / test::kDegree;
        double spot = 1.0;
        if (angle > 14.0) {
            spot = 0.0;
        } else if (angle > 10.0) {
            double t = (std::cos(angle * test::kDegree) - std::cos(14 * test::kDegree)) / (std::cos(10 * test::kDegree) - std::cos(14 * test::kDegree));
            spot = t * t * (3 - 2 * t);
        }
        double expected = spot * 4.0 / glm::length(to_light);  // diffuse 1 x N.L
        EXPECT_NEAR(img.at(x, 0).r, expected, test::kBackendTolerance) << "pixel " << x << " at " << angle << " degrees";
        full += angle < 10.0;
        dark += angle > 14.0;
        edge += angle > 10.5 && angle < 13.5;
    }
    EXPECT_GT(full, 20);
    EXPECT_GT(dark, 20);
    EXPECT_GT(edge, 10);
}

// Twice the distance, a quarter of the light; at falloff_distance, the light's colour.
TEST_P(LightTypes, InverseSquareFalloffGivesTheColourAtTheReferenceDistance) {
    double centre[2];
    for (int i = 0; i < 2; ++i) {
        double height = i == 0 ? 2.0 : 4.0;
        Scene s = test::scene_from_text(floor_scene(fmt::format(R"(
            [[light]]
            position = [0, {}, 0]
            color = [0.8, 0.6, 0.4]
            falloff = "inverse_square"
            falloff_distance = 2
        )",
                                                                height)));
        s.render.width = 3;
        s.render.height = 3;
        centre[i] = render(s).at(1, 1).r;
        EXPECT_NEAR(centre[i], 0.8 * std::pow(2.0 / height, 2.0), test::kBackendTolerance) << "light at height " << height;
    }
    EXPECT_NEAR(centre[0] / centre[1], 4.0, 1e-4);
}

// POV-Ray's fading, with any fade_power: 2 / (1 + (d / fade_distance)^fade_power) times the
// colour, 1 at fade_distance, on both backends (the spot is in the same place as the point).
TEST_P(LightTypes, PovRayFadeFollowsItsFormulaForAnyPower) {
    for (double power : {1.0, 2.0, 3.5}) {
        for (double height : {1.0, 2.0, 5.0}) {
            Scene s = test::scene_from_text(floor_scene(fmt::format(R"(
                [[light]]
                position = [0, {}, 0]
                color = [0.8, 0.6, 0.4]
                fade_distance = 2
                fade_power = {}
            )",
                                                                    height, power)));
            s.render.width = 3;
            s.render.height = 3;
            const double expected = 0.8 * 2.0 / (1.0 + std::pow(height / 2.0, power));
            EXPECT_NEAR(render(s).at(1, 1).r, expected, test::kBackendTolerance) << "power " << power << ", height " << height;
        }
    }
}

// A wall x = 0 of height 1 between the floor x > 0 and an area light at height 5, centred 2
// to the left, `size` wide along x, 8 x 8 samples at their cells' centres. A point light at
// -a over the wall's top shades the floor up to x = a / 4, so the penumbra runs from the
// nearest sample column's line to the farthest's: size * (n - 1) / n / 4.
struct Penumbra {
    double start;  // first floor x that sees part of the light
    double end;    // first floor x that sees all of it
};

Penumbra measure_penumbra(LightTypes& test, double size, bool jitter) {
    std::string light = fmt::format(R"(
        [[light]]
        type = "area"
        position = [-2, 5, 0]
        edge_u = [{}, 0, 0]
        edge_v = [0, 0, {}]
        samples = 8
        jitter = {}
    )",
                                    size, size, jitter ? "true" : "false");
    const char* wall = R"(
        [[object]]
        type = "rectangle"
        corner = [0, 0, -50]
        edge_u = [0, 1, 0]
        edge_v = [0, 0, 100]
    )";
    Scene lit = test::scene_from_text(floor_scene(light));
    Scene shadowed = test::scene_from_text(floor_scene(light + wall));
    for (Scene* s : {&lit, &shadowed}) {
        s->camera.eye = {2.0, 10.0, 0.0};  // look at 0 < x < 4
        s->camera.look_at = {2.0, 0.0, 0.0};
        s->render.width = 401;
        s->camera.fov_deg = 0.06;  // 0.0105 units per pixel
    }
    FloatImage a = test::render_on(test.GetParam(), lit), b = test::render_on(test.GetParam(), shadowed);
    Penumbra p{-1, -1};
    for (int x = 0; x < a.width; ++x) {
        double seen = b.at(x, 0).r / a.at(x, 0).r;  // the fraction of the light this point sees
        double fx = floor_point(lit, x, 0).x;
        if (fx <= 0.0) continue;  // left of the wall: nothing in the way
        if (p.start < 0 && seen > 0.0) p.start = fx;
        if (p.end < 0 && seen == 1.0) p.end = fx;
    }
    return p;
}

TEST_P(LightTypes, AreaLightPenumbraWidensWithTheLightsSize) {
    const double pixel = 0.0105;
    double width[2];
    for (int i = 0; i < 2; ++i) {
        double size = i == 0 ? 1.0 : 2.0;
        Penumbra p = measure_penumbra(*this, size, false);
        double first = 2.0 - size / 2 + size / 16, last = 2.0 + size / 2 - size / 16;  // sample columns' distances
        EXPECT_NEAR(p.start, first / 4, 1.5 * pixel) << "size " << size;
        EXPECT_NEAR(p.end, last / 4, 1.5 * pixel) << "size " << size;
        width[i] = p.end - p.start;
    }
    EXPECT_NEAR(width[1] / width[0], 2.0, 0.1);
    EXPECT_GT(width[0], 20 * pixel);
}

// Jittered samples spread over the whole cell: the penumbra reaches at most to the lines of the
// light's edges, and is wider than the unjittered one.
TEST_P(LightTypes, JitteredAreaLightPenumbraSpansTheWholeLight) {
    const double pixel = 0.0105;
    Penumbra centred = measure_penumbra(*this, 2.0, false);
    Penumbra jittered = measure_penumbra(*this, 2.0, true);
    EXPECT_GE(jittered.start, 1.0 / 4 - pixel);
    EXPECT_LE(jittered.end, 3.0 / 4 + pixel);
    EXPECT_GT(jittered.end - jittered.start, centred.end - centred.start);
}

// A specular-only floor: every pixel is k_s I (N.H)^n (Blinn) or k_s I (R.L)^n (Phong), and
// the brightest pixel is where the floor mirrors the light into the camera.
TEST_P(LightTypes, HighlightFollowsItsFormulaAndPeaksAtTheMirrorPoint) {
    for (std::string model : {"blinn", "phong"}) {
        Scene s = test::scene_from_text(fmt::format(R"(
            [render]
            width = 41
            height = 41
            samples = 1
            [camera]
            eye = [0, 2, -4]
            look_at = [0, 0, -1.5]
            fov = 30
            [[light]]
            position = [0, 4, 3]
            color = [0.9, 0.9, 0.9]
            [material.floor]
            ambient = 0
            diffuse = 0
            specular = 0.8
            shininess = 60
            highlight = "{}"
            [[object]]
            type = "plane"
            normal = [0, 1, 0]
            material = "floor"
        )",
                                                    model));
        FloatImage img = render(s);
        const dvec3 eye(0, 2, -4), light(0, 4, 3), n(0, 1, 0);
        int best_x = -1, best_y = -1;
        float best = -1.0f;
        for (int y = 0; y < img.height; ++y) {
            for (int x = 0; x < img.width; ++x) {
                dvec3 p = floor_point(s, x, y);
                dvec3 v = glm::normalize(eye - p), l = glm::normalize(light - p);
                double c = model == "blinn" ? glm::dot(n, glm::normalize(l + v)) : glm::dot(2.0 * glm::dot(n, v) * n - v, l);
                double expected = c > 0 ? 0.8 * 0.9 * std::pow(c, 60.0) : 0.0;
                EXPECT_NEAR(img.at(x, y).r, expected, test::kBackendTolerance) << model << " pixel " << x << "," << y;
                if (img.at(x, y).r > best) best = img.at(x, y).r, best_x = x, best_y = y;
            }
        }
        // The mirror point: the line from the eye to the light mirrored below the floor.
        dvec3 mirrored(0, -4, 3);
        dvec3 m = eye + (2.0 / 6.0) * (mirrored - eye);
        dvec3 at = floor_point(s, best_x, best_y);
        EXPECT_LT(glm::length(at - m), 0.1) << model;
        EXPECT_NEAR(best, 0.72, 0.01) << model;  // k_s I at its peak
    }
}

// A negative colour is POV-Ray's negative light: its ambient and diffuse terms subtract from the
// highlight, which they do not tint. The floor seen from above, its light straight overhead.
TEST_P(LightTypes, ANegativeColourSubtractsItsAmbientAndDiffuseLight) {
    Scene s = test::scene_from_text(floor_scene(R"(
        [[light]]
        position = [0, 10, 0]
        color = [0.9, 0.9, 0.9]
        [material.dark]
        color = [-0.5, 0.25, 0]
        ambient = 0.1
        diffuse = 0.5
        specular = 0.8
        shininess = 60
        [[object]]
        type = "plane"
        point = [0, 0.01, 0]
        normal = [0, 1, 0]
        material = "dark"
    )"));
    FloatImage img = render(s);
    const dvec3 eye(0, 10, 0), light(0, 10, 0), n(0, 1, 0);
    for (int x = 0; x < img.width; x += 20) {
        const dvec3 below = floor_point(s, x, 0);  // on y = 0; the dark plane is 0.01 above
        const dvec3 p = eye + (1.0 - 0.01 / eye.y) * (below - eye);
        const dvec3 v = glm::normalize(eye - p), l = glm::normalize(light - p);
        const double spec = 0.8 * 0.9 * std::pow(std::max(0.0, glm::dot(2.0 * glm::dot(n, v) * n - v, l)), 60.0);
        const double lit = 0.1 + 0.5 * glm::dot(n, l) * 0.9;  // ambient light 1, the light's diffuse share
        EXPECT_NEAR(img.at(x, 0).r, -0.5 * lit + spec, test::kBackendTolerance) << "pixel " << x;
        EXPECT_NEAR(img.at(x, 0).g, 0.25 * lit + spec, test::kBackendTolerance) << "pixel " << x;
        EXPECT_NEAR(img.at(x, 0).b, spec, test::kBackendTolerance) << "pixel " << x;
    }
    EXPECT_LT(img.at(100, 0).r, img.at(100, 0).b) << "the negative red takes light away";
}

INSTANTIATE_TEST_SUITE_P(Backends, LightTypes, testing::Values(Backend::Gpu, Backend::Cpu),
                         [](const auto& info) { return test::backend_name(info.param); });

}  // namespace
}  // namespace lancer

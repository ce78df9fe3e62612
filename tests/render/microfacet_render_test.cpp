// Microfacet materials rendered: the white furnace (a sphere in a uniform white environment,
// lit by nothing else: a lossless material shows exactly the environment at every roughness, a
// lossy one less) on each backend, through the whole ray tree and its sampling.
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

constexpr int kSize = 32;

// A unit sphere of `material` filling most of a 32 x 32 view, in a white environment.
Scene furnace(const std::string& material, int samples = 4) {
    return test::scene_from_text(fmt::format(R"(
        [render]
        width = {0}
        height = {0}
        samples = {1}
        max_depth = 12
        background = [1, 1, 1]
        [camera]
        eye = [0, 0, -4]
        look_at = [0, 0, 0]
        fov = 30
        [material.m]
        model = "microfacet"
        {2}
        [[object]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
        material = "m"
    )", kSize, samples, material));
}

// The mean colour of the pixels whose every camera ray meets the sphere (a margin of one pixel
// inside its outline), and how many there are.
struct SphereMean {
    dvec3 mean{0.0};
    int pixels = 0;
};
SphereMean mean_on_sphere(const Scene& scene, const FloatImage& image) {
    CameraBasis cam = make_camera_basis(scene.camera, kSize, kSize);
    SphereMean out;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            bool inside = true;
            for (double dy : {-0.5, 1.5})
                for (double dx : {-0.5, 1.5}) {
                    dvec3 d = glm::normalize(camera_ray_direction(cam, x + dx, y + dy, kSize, kSize));
                    double b = glm::dot(cam.eye, d), c = glm::dot(cam.eye, cam.eye) - 1.0;
                    inside = inside && b * b - c > 0.0;
                }
            if (!inside) continue;
            out.mean += dvec3(image.at(x, y));
            ++out.pixels;
        }
    out.mean /= double(out.pixels);
    return out;
}

class Furnace : public testing::TestWithParam<Backend> {
protected:
    SphereMean measure(const std::string& material) {
        Scene scene = furnace(material);
        FloatImage image = test::render_on(GetParam(), scene);
        SphereMean m = mean_on_sphere(scene, image);
        EXPECT_GT(m.pixels, 300) << material;
        return m;
    }
};

TEST_P(Furnace, LosslessMetalReturnsTheEnvironmentAtEveryRoughness) {
    for (double r : {0.0, 0.05, 0.2, 0.5, 0.8, 1.0}) {
        SphereMean m = measure(fmt::format("metal = \"perfect\"\nroughness = {}", r));
        // 16 samples a pixel over ~500 pixels: the Monte Carlo error of the mean is ~0.3%.
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.mean[c], 1.0, 0.01) << "roughness " << r << " channel " << c;
    }
}

TEST_P(Furnace, LossyMetalsReturnLess) {
    for (double r : {0.0, 0.3, 1.0}) {
        SphereMean gold = measure(fmt::format("metal = \"gold\"\nroughness = {}", r));
        EXPECT_LT(gold.mean.r, 0.99) << r;
        EXPECT_LT(gold.mean.b, 0.6) << r;  // gold reflects little blue
        EXPECT_GT(gold.mean.b, 0.1) << r;
        SphereMean tinted = measure(fmt::format("metal = \"perfect\"\ncolor = [0.5, 0.5, 0.5]\nroughness = {}", r));
        if (r == 0.0) {
            // A mirror: one bounce off a convex sphere returns exactly the tint.
            EXPECT_NEAR(tinted.mean.g, 0.5, 0.005);
        } else {
            // Light that bounces between rough microfacets is tinted at every bounce.
            EXPECT_LT(tinted.mean.g, 0.5) << r;
            EXPECT_GT(tinted.mean.g, 0.2) << r;
        }
    }
}

// Glass has no multiple-scattering term: smooth glass returns everything, rough glass loses
// the light that would bounce between its microfacets, more the rougher it is (measured on the
// CPU reference: 0.993 at roughness 0.2, 0.977 at 0.3, 0.86 at 0.5, 0.36 at 1; a ray crosses at
// least two rough interfaces here). docs/scene-format.md says so.
TEST_P(Furnace, SmoothClearGlassReturnsTheEnvironmentAndRoughGlassNoMore) {
    SphereMean smooth = measure("transmission = 1\nior = 1.5\nroughness = 0");
    EXPECT_NEAR(smooth.mean.g, 1.0, 0.01);
    double previous = smooth.mean.g;
    for (double r : {0.2, 0.5, 1.0}) {
        SphereMean rough = measure(fmt::format("transmission = 1\nior = 1.5\nroughness = {}", r));
        EXPECT_LT(rough.mean.g, previous + 0.005) << r;
        EXPECT_GT(rough.mean.g, r <= 0.2 ? 0.98 : 0.3) << r;
        previous = rough.mean.g;
    }
    SphereMean absorbing = measure("transmission = 1\nior = 1.5\nroughness = 0.3\nabsorption = [0, 0, 2]");
    EXPECT_LT(absorbing.mean.b, 0.8 * absorbing.mean.g);
}

INSTANTIATE_TEST_SUITE_P(Backends, Furnace, testing::Values(Backend::Gpu, Backend::Cpu),
                         [](const auto& info) { return test::backend_name(info.param); });

}  // namespace
}  // namespace lancer

// Photon-mapped renders against optics worked out by hand, on each backend: a floor under a
// point light and a mirror shows, besides the light's own irradiance (shadow rays), the
// irradiance of the light's mirror image Phi cos(theta) / (4 pi d^2), carried by caustic photons;
// and the same scene and seed give the same bytes whatever the thread count.
#include <cmath>
#include <cstring>
#include <string>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "cpu/cpu_renderer.hpp"
#include "cpu/lights.hpp"
#include "scene/camera.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

using test::Backend;


// A white diffuse floor (y = 0) and a perfect mirror facing it at y = 3; a 100 W point light at
// height 2.4 between them. Photons stop after two interactions, so the only stored ones went
// light -> mirror -> floor: the caustic map holds the light of the mirror image at height 3.6.
std::string mirror_scene(int passes, int photons) {
    return fmt::format(R"(
        [render]
        width = 24
        height = 16
        samples = 1
        max_depth = 0
        [camera]
        eye = [0, 2, -4]
        look_at = [0, 0, 0.5]
        fov = 50
        [ambient]
        color = [0, 0, 0]
        [photons]
        count = {}
        passes = {}
        caustic_radius = 0.15
        global_radius = 0.15
        max_bounces = 2
        [material.floor]
        ambient = 0
        diffuse = 1
        [material.mirror]
        ambient = 0
        diffuse = 0
        reflection = 1
        [[object]]
        type = "plane"
        normal = [0, 1, 0]
        material = "floor"
        [[object]]
        type = "plane"
        point = [0, 3, 0]
        normal = [0, -1, 0]
        material = "mirror"
        [[light]]
        position = [0.3, 2.4, 0.8]
        power = 100
    )", photons, passes);
}

class PhotonRender : public testing::TestWithParam<Backend> {};

TEST_P(PhotonRender, FloorShowsTheLightAndItsMirrorImage) {
    const int passes = 6, photons = 250000;
    Scene scene = test::scene_from_text(mirror_scene(passes, photons));
    FloatImage image = test::render_on(GetParam(), scene);
    const dvec3 light(0.3, 2.4, 0.8), image_light(0.3, 3.6, 0.8);
    const double power = 100.0;
    CameraBasis cam = make_camera_basis(scene.camera, scene.render.width, scene.render.height);
    int checked = 0;
    double photon_part = 0.0, expected_part = 0.0;
    auto irradiance = [&](const dvec3& q, const dvec3& p) {
        dvec3 to = q - p;
        double d2 = glm::dot(to, to);
        return power * (to.y / std::sqrt(d2)) / (4.0 * kPi * d2);
    };
    for (int y = 0; y < scene.render.height; ++y)
        for (int x = 0; x < scene.render.width; ++x) {
            // Each pass samples the pixel at its own place (docs/scene-format.md): the expected
            // radiance is the mean over those places of (k_d / pi) (E_light + E_image), k_d = 1.
            double expected = 0.0, direct = 0.0, e_image = 0.0;
            bool on_floor = true;
            for (int k = 0; k < passes; ++k) {
                cpu::PassSample s = cpu::photon_pass_sample(x, y, 1, k);
                dvec3 d = glm::normalize(camera_ray_direction(cam, x + s.dx, y + s.dy, scene.render.width, scene.render.height));
                dvec3 p = cam.eye + (-cam.eye.y / d.y) * d;
                on_floor = on_floor && d.y < -0.05 && glm::length(glm::dvec2(p.x, p.z)) <= 2.5;
                direct += irradiance(light, p) / kPi / passes;
                e_image += irradiance(image_light, p) / passes;
            }
            if (!on_floor) continue;
            expected = direct + e_image / kPi;
            double got = image.at(x, y).g;
            // About photons * passes * (the image's irradiance times the disc's area over the
            // power) photons land in the gather discs (0.7: the radii shrink over the passes);
            // allow 4 standard deviations, and 2% for the disc's averaging of a curved field.
            double in_disc = photons * passes * e_image * kPi * 0.15 * 0.15 / power * 0.7;
            double tolerance = 4.0 * (e_image / kPi) / std::sqrt(in_disc) + 0.02 * expected;
            EXPECT_NEAR(got, expected, tolerance) << "pixel " << x << ", " << y << ": direct alone " << direct;
            EXPECT_GT(got, direct + 0.5 * e_image / kPi) << "pixel " << x << ", " << y;  // the mirror's light is there
            photon_part += got - direct;
            expected_part += e_image / kPi;
            ++checked;
        }
    EXPECT_GT(checked, 100);
    // Over all pixels the photons' share is known far better: within 4% (a wrong power, radius or
    // factor of pi moves it by far more).
    EXPECT_NEAR(photon_part / expected_part, 1.0, 0.04);
}

INSTANTIATE_TEST_SUITE_P(Backends, PhotonRender, testing::Values(Backend::Gpu, Backend::Cpu),
                         [](const auto& info) { return test::backend_name(info.param); });

// The passes of a photon render differ only in their frame constants: the GPU packs the scene
// once for all of them.
TEST(PhotonRenderPacking, TheGpuPacksTheSceneOncePerRender) {
    GpuRenderer& gpu = test::gpu_renderer();
    const std::size_t before = gpu.scenes_packed();
    gpu.render(test::scene_from_text(mirror_scene(3, 2000)), {});
    EXPECT_EQ(gpu.scenes_packed(), before + 1);
}

TEST(PhotonRenderDeterminism, CpuGivesTheSameBytesOnAnyNumberOfThreads) {
    Scene scene = test::scene_from_text(mirror_scene(3, 20000));
    Scene small = test::shipped_scene("cornell", 40, 40);
    small.photons->count = 5000;
    small.photons->passes = 3;
    for (const Scene* s : {&scene, &small}) {
        FloatImage one = CpuRenderer(1).render(*s, {}), three = CpuRenderer(3).render(*s, {});
        ASSERT_EQ(one.pixels.size(), three.pixels.size());
        EXPECT_EQ(0, std::memcmp(one.pixels.data(), three.pixels.data(), one.pixels.size() * sizeof(glm::vec4)));
    }
}

}  // namespace
}  // namespace lancer

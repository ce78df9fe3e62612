// lavapipe silently ends all loops of a shader invocation after 65535 iterations in total.
// lancer detects invocations that were cut short, renders their band again with one sample per
// invocation, and reports a clear error when even one sample is too much.
#include <string>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// Brute force over `spheres` spheres, `lights` lights and mirror bounces: loop iterations grow
// as samples x bounces x (1 + lights) x spheres.
std::string heavy_scene(int spheres, int lights) {
    std::string s = R"(
        [render]
        width = 16
        height = 8
        samples = 3
        max_depth = 5
        [camera]
        eye = [0, 0, -30]
        look_at = [0, 0, 0]
        fov = 40
        [material.mirror]
        color = [0.5, 0.6, 0.7]
        reflection = 0.9
    )";
    for (int i = 0; i < lights; ++i)
        s += "[[light]]\nposition = [" + std::to_string(-20 + i) + ", 20, -20]\ncolor = [0.02, 0.02, 0.02]\n";
    for (int i = 0; i < spheres; ++i)
        s += "[[object]]\ntype = \"sphere\"\nmaterial = \"mirror\"\nradius = 0.45\ncenter = [" + std::to_string(i % 12 - 6) +
             ", " + std::to_string(i / 12 - 5) + ", " + std::to_string((i * 7) % 5) + "]\n";
    return s;
}

bool is_lavapipe() { return test::gpu_renderer().context().info().driver_id == VK_DRIVER_ID_MESA_LLVMPIPE; }

TEST(LoopLimit, CutShortBandsAreRenderedAgainAndMatchTheReference) {
    if (!is_lavapipe()) GTEST_SKIP() << "only lavapipe limits loop iterations";
    Scene scene = test::scene_from_text(heavy_scene(300, 30));
    GpuRenderer brute(gpu::ContextOptions{"", true}, Acceleration::BruteForce);
    Rgb8Image gpu = to_srgb8(brute.render(scene, {}));
    EXPECT_GT(brute.bands_rerendered(), 0u) << "the scene no longer exceeds the limit at 9 samples per invocation";
    Rgb8Image cpu = to_srgb8(CpuRenderer().render(scene, {}));
    ImageDiff d = compare_images(gpu, cpu, 4);
    EXPECT_GE(d.psnr_db, 40.0);
    EXPECT_LE(d.fraction_over, 0.01);  // 128 pixels: one may sit on an edge
}

TEST(LoopLimit, TooMuchWorkForOneSampleIsAClearError) {
    if (!is_lavapipe()) GTEST_SKIP() << "only lavapipe limits loop iterations";
    Scene scene = test::scene_from_text(heavy_scene(200, 250));
    GpuRenderer brute(gpu::ContextOptions{"", true}, Acceleration::BruteForce);
    try {
        brute.render(scene, {});
        FAIL() << "rendered a scene beyond the driver's loop limit";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("loop iterations"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lancer

// No NaN or infinity ever reaches a picture: every scene in scenes/ (new ones are picked up
// automatically) and every degenerate scene in tests/data/degenerate/ is rendered small by both
// backends into the float buffer, and every value of every pixel must be finite. An 8-bit PNG
// would hide a NaN (it clamps to 0 or 255); the float buffer cannot.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "scene/animation.hpp"
#include "scene/load_scene.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> scenes_to_scan() {
    std::vector<std::string> paths = test::scene_files();
    for (const auto& e : fs::directory_iterator(test::source_path("tests/data/degenerate")))
        if (e.path().extension() == ".toml") paths.push_back(e.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

// Small, 2 x 2 samples (so the sample grid's offsets are covered), the scene's aspect ratio; an
// odd width puts a pixel centre on the optical axis, where degenerate shapes sit.
Scene small_version(const std::string& path) {
    Scene scene = load_scene(path);
    if (scene.animation) scene = scene_at(scene, 0.5);
    RenderSettings& r = scene.render;
    r.height = std::max(1, r.height * 41 / r.width) | 1;
    r.width = 41;
    r.samples = std::min(r.samples, 2);
    if (scene.photons) {  // two passes of a few photons: every code path, in a fraction of a second
        scene.photons->count = std::min(scene.photons->count, 2000);
        scene.photons->passes = std::min(scene.photons->passes, 2);
    }
    return scene;
}

// "pixel (x, y) channel c is nan" for the first few offenders.
std::string non_finite_values(const FloatImage& image) {
    std::string report;
    int found = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 4; ++c) {
                float v = image.pixels[std::size_t(y) * image.width + x][c];
                if (std::isfinite(v)) continue;
                if (++found <= 5) report += "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " +
                                            std::to_string(c) + " is " + std::to_string(v) + "; ";
            }
    if (found > 5) report += std::to_string(found - 5) + " more";
    return report;
}

std::string test_name(const std::string& path) {
    std::string name = fs::path(path).parent_path().filename().string() + "_" + fs::path(path).stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

class FiniteOutput : public testing::TestWithParam<std::string> {};

TEST_P(FiniteOutput, GpuWritesOnlyFiniteValues) {
    Scene scene = small_version(GetParam());
    FloatImage image = test::gpu_renderer().render(scene, {});
    ASSERT_EQ(image.pixels.size(), std::size_t(scene.render.width) * scene.render.height);
    EXPECT_EQ(non_finite_values(image), "");
}

TEST_P(FiniteOutput, CpuWritesOnlyFiniteValues) {
    Scene scene = small_version(GetParam());
    FloatImage image = CpuRenderer().render(scene, {});
    ASSERT_EQ(image.pixels.size(), std::size_t(scene.render.width) * scene.render.height);
    EXPECT_EQ(non_finite_values(image), "");
}

INSTANTIATE_TEST_SUITE_P(Scenes, FiniteOutput, testing::ValuesIn(scenes_to_scan()),
                         [](const auto& info) { return test_name(info.param); });

// The scan itself can fail: a NaN planted in a picture is reported with its pixel.
TEST(FiniteOutputScan, FindsANanAndAnInfinity) {
    FloatImage image(3, 2);
    EXPECT_EQ(non_finite_values(image), "");
    image.pixels[4].g = std::nanf("");
    image.pixels[5].a = INFINITY;
    std::string report = non_finite_values(image);
    EXPECT_NE(report.find("pixel (1, 1) channel 1 is nan"), std::string::npos) << report;
    EXPECT_NE(report.find("pixel (2, 1) channel 3 is inf"), std::string::npos) << report;
}

}  // namespace
}  // namespace lancer

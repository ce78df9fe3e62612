// Every scene in scenes/ rendered by both backends at reduced size must agree, under the image
// tests' metric (test::expect_same_picture: PSNR >= 40 dB, at most 0.1% of pixels off by more
// than 4/255; the reasons for those numbers are given there).
#include <filesystem>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "scene/load_scene.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// Reduced size, same aspect ratio, 240 pixels wide so features stay visible. Shapes that are not
// cheap (the registry's SHAPE_CHEAP) cost the reference far more: ~50 us per ray and patch for
// Bezier surfaces (an eigenvalue problem each), so scenes with them are tested at 128 pixels and
// 2 x 2 samples.
void shrink(Scene& scene) {
    RenderSettings& r = scene.render;
    bool exact_surfaces = std::any_of(scene.objects.begin(), scene.objects.end(), [](const Object& o) {
        return !shape_has(shape_type(o.shape), SHAPE_CHEAP);
    });
    int width = exact_surfaces ? 128 : 240;
    if (exact_surfaces) r.samples = std::min(r.samples, 2);
    r.height = std::max(1, r.height * width / r.width);
    r.width = width;
}

class BackendsAgree : public testing::TestWithParam<std::string> {};

TEST_P(BackendsAgree, GpuMatchesCpuReference) {
    Scene scene = load_scene(GetParam());
    shrink(scene);
    Rgb8Image gpu = to_srgb8(test::gpu_renderer().render(scene, {}));  // a = gpu, b = cpu
    Rgb8Image cpu = to_srgb8(CpuRenderer().render(scene, {}));
    test::expect_same_picture("backends-" + std::filesystem::path(GetParam()).stem().string(), gpu, cpu);
}

// Photon-mapped scenes are estimates with noise of their own on each backend (float and double
// send a photon path apart after a few bounces): they agree statistically, which
// photon_agreement_test.cpp checks, not pixel by pixel.
std::vector<std::string> scenes_without_photons() {
    std::vector<std::string> out;
    for (const std::string& path : test::scene_files())
        if (test::read_file(path).find("\n[photons]") == std::string::npos) out.push_back(path);
    return out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, BackendsAgree, testing::ValuesIn(scenes_without_photons()), [](const auto& info) {
    return std::filesystem::path(info.param).stem().string();
});

}  // namespace
}  // namespace lancer

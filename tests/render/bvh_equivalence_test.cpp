// The BVH only changes which objects are tested, never the answer: on every scene, each backend
// renders the same bytes with its BVH as with brute force; and the GPU's direction grids, forced
// wherever the scene allows them, the same as its BVH alone.
#include <filesystem>
#include <memory>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "scene/load_scene.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

class BvhEquivalence : public testing::TestWithParam<std::string> {
protected:
    // Created once for the suite, destroyed before the validation layer's messages are counted.
    static void SetUpTestSuite() {
        bvh_renderer = std::make_unique<GpuRenderer>(gpu::ContextOptions{"", true}, Acceleration::BvhAlways);
        brute_renderer = std::make_unique<GpuRenderer>(gpu::ContextOptions{"", true}, Acceleration::BruteForce);
        bvh_alone = std::make_unique<GpuRenderer>(gpu::ContextOptions{"", true}, Acceleration::BvhAlways);
        bvh_alone->set_grid_use(gpu::GridUse::Never);
        grids_forced = std::make_unique<GpuRenderer>(gpu::ContextOptions{"", true});
        grids_forced->set_grid_use(gpu::GridUse::Forced);
    }
    static void TearDownTestSuite() {
        bvh_renderer.reset();
        brute_renderer.reset();
        bvh_alone.reset();
        grids_forced.reset();
    }
    static std::unique_ptr<GpuRenderer> bvh_renderer;  // a tree even over a handful of primitives
    static std::unique_ptr<GpuRenderer> brute_renderer;
    static std::unique_ptr<GpuRenderer> bvh_alone;     // a tree, and no direction grids
    static std::unique_ptr<GpuRenderer> grids_forced;  // grids wherever the scene allows, cost aside
};
std::unique_ptr<GpuRenderer> BvhEquivalence::bvh_renderer;
std::unique_ptr<GpuRenderer> BvhEquivalence::brute_renderer;
std::unique_ptr<GpuRenderer> BvhEquivalence::bvh_alone;
std::unique_ptr<GpuRenderer> BvhEquivalence::grids_forced;

// Every pixel is compared exactly, so a small image still catches a node or leaf the tree loses;
// the GPU's brute force over thousands of parametric cells is what makes these tests slow, so
// the GPU renders a quarter of the CPU's pixels.
Scene small(const std::string& path, int width) {
    Scene scene = load_scene(path);
    scene.render.height = std::max(1, scene.render.height * width / scene.render.width);
    scene.render.width = width;
    scene.render.samples = 1;  // anti-aliasing adds nothing to this comparison
    if (scene.photons) {  // the photons' paths use the same queries: a few show any difference
        scene.photons->count = std::min(scene.photons->count, 2000);
        scene.photons->passes = 1;
    }
    return scene;
}

TEST_P(BvhEquivalence, CpuBvhMatchesBruteForce) {
    Scene scene = small(GetParam(), 96);
    Rgb8Image bvh = to_srgb8(CpuRenderer(0, Acceleration::BvhAlways).render(scene, {}));
    Rgb8Image brute = to_srgb8(CpuRenderer(0, Acceleration::BruteForce).render(scene, {}));
    EXPECT_EQ(bvh.bytes, brute.bytes);
}

TEST_P(BvhEquivalence, GpuBvhMatchesBruteForce) {
    Scene scene = small(GetParam(), 48);
    Rgb8Image brute;
    try {
        brute = to_srgb8(brute_renderer->render(scene, {}));
    } catch (const UserError& e) {
        // Testing every one of thousands of parametric cells for every camera, shadow and
        // reflection ray exceeds lavapipe's 65535 loop iterations per invocation; lancer reports
        // that instead of a wrong image. Camera rays alone fit: the first hit of every pixel
        // (t, u, v, patch) must then be the same, bit for bit.
        FloatImage bvh_hits = bvh_renderer->render_hits(scene);
        FloatImage brute_hits = brute_renderer->render_hits(scene);
        ASSERT_EQ(bvh_hits.pixels.size(), brute_hits.pixels.size());
        int differ = 0, hits = 0;
        for (std::size_t i = 0; i < bvh_hits.pixels.size(); ++i) {
            differ += bvh_hits.pixels[i] != brute_hits.pixels[i];
            hits += bvh_hits.pixels[i].x >= 0.0f;
        }
        EXPECT_EQ(differ, 0) << "pixels whose first hit differs (full render: " << e.what() << ")";
        EXPECT_GT(hits, 0);
        return;
    }
    Rgb8Image bvh = to_srgb8(bvh_renderer->render(scene, {}));
    ImageDiff d = compare_images(bvh, brute, 0);
    EXPECT_EQ(d.max_abs, 0) << d.fraction_over * bvh.width * bvh.height << " pixels differ";
    if (d.max_abs) test::save_comparison("bvh-gpu-" + std::filesystem::path(GetParam()).stem().string(), bvh, brute);
}

// Every float of every pixel: the grids list, per direction, every primitive a ray can hit, and
// ties between hits go by a stable key, so the hits are the same whichever way they were found.
TEST_P(BvhEquivalence, GpuGridsForcedMatchTheBvhAlone) {
    Scene scene = small(GetParam(), 48);
    const FloatImage grids = grids_forced->render(scene, {});
    const FloatImage bvh = bvh_alone->render(scene, {});
    ASSERT_EQ(grids.pixels.size(), bvh.pixels.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < grids.pixels.size(); ++i) differ += grids.pixels[i] != bvh.pixels[i];
    EXPECT_EQ(differ, 0u) << "pixels that differ";
    if (differ)
        test::save_comparison("grids-gpu-" + std::filesystem::path(GetParam()).stem().string(), to_srgb8(grids), to_srgb8(bvh));
}

INSTANTIATE_TEST_SUITE_P(Scenes, BvhEquivalence, testing::ValuesIn(test::scene_files()), [](const auto& info) {
    return std::filesystem::path(info.param).stem().string();
});

}  // namespace
}  // namespace lancer

// The same scene, options and backend give the same bytes, run after run: separate processes
// writing PNGs on both backends, and in one process the CPU reference on one thread and on many
// (rows are handed out to threads in whatever order they ask, so any dependence on the order
// would show), and the GPU rendering twice.
#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// A plain scene, Bezier patches and a parametric surface: each backend's every code path.
const char* const kScenes[] = {"seed", "teapot", "torus"};

std::string png_of(const std::string& scene, const std::string& backend, int run) {
    std::string out = test::output_dir() + "/determinism-" + scene + "-" + backend + "-" + std::to_string(run) + ".png";
    auto r = test::run_lancer("render " + test::source_path("scenes/" + scene + ".toml") + " --backend " + backend +
                              " --width 48 --height 27 --samples 2 -q -o " + out);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return test::read_file(out);
}

class Determinism : public testing::TestWithParam<std::string> {};

TEST_P(Determinism, TwoRunsWriteTheSamePngBytes) {
    for (const char* scene : kScenes) {
        std::string first = png_of(scene, GetParam(), 1);
        ASSERT_GT(first.size(), 100u) << scene;
        EXPECT_TRUE(first == png_of(scene, GetParam(), 2)) << scene << " on " << GetParam();
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, Determinism, testing::Values("gpu", "cpu"));

Scene small(const char* name) {
    return test::shipped_scene(name, 48, 27, 2);
}

bool same_floats(const FloatImage& a, const FloatImage& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(a.pixels[0])) == 0;
}

TEST(Determinism, CpuReferenceIsTheSameOnOneThreadAndOnSeven) {
    for (const char* name : kScenes) {
        Scene scene = small(name);
        EXPECT_TRUE(same_floats(CpuRenderer(1).render(scene, {}), CpuRenderer(7).render(scene, {}))) << name;
    }
}

TEST(Determinism, GpuRendersTheSameFloatsTwice) {
    for (const char* name : kScenes) {
        Scene scene = small(name);
        FloatImage first = test::gpu_renderer().render(scene, {});
        EXPECT_TRUE(same_floats(first, test::gpu_renderer().render(scene, {}))) << name;
    }
}

}  // namespace
}  // namespace lancer

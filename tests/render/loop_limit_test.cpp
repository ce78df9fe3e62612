// lavapipe up to Mesa 22.3 silently ends all loops of a shader invocation after 65535 iterations
// in total. There, lancer detects invocations that were cut short, renders their band again with
// one sample per invocation, and reports a clear error when even one sample is too much; on a
// driver without the limit the same scenes simply render right (gpu/vulkan/driver_quirks.hpp).
#include <string>

#include <gtest/gtest.h>

#include "core/process_limits.hpp"
#include "cpu/cpu_renderer.hpp"
#include "gpu/vulkan/driver_quirks.hpp"
#include "support/gpu_kernel.hpp"
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

bool driver_limits_loops() { return gpu::limits_loop_iterations(test::gpu_renderer().context().info()); }

void expect_matches_the_reference(const Scene& scene, const Rgb8Image& gpu) {
    Rgb8Image cpu = to_srgb8(CpuRenderer().render(scene, {}));
    ImageDiff d = compare_images(gpu, cpu, 4);
    EXPECT_GE(d.psnr_db, 40.0);
    EXPECT_LE(d.fraction_over, 0.01);  // 128 pixels: one may sit on an edge
}

// The rule in driver_quirks must hold for the driver the tests run on: a loop of 100,000
// iterations counted on the device, and a two-iteration loop after it (the tracer's probe).
TEST(LoopLimit, TheRuleForThisDriverAgreesWithAMeasurement) {
    test::GpuKernel kernel(R"(#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "interface.glsl"
layout(local_size_x = 1) in;
void main() {
    uint n = uint(pixels[0].x), long_loop = 0u, probe = 0u;
    for (uint i = 0u; i < n; ++i) ++long_loop;
    for (uint i = 0u; i < uint(pixels[0].y); ++i) ++probe;
    pixels[1] = vec4(float(long_loop), float(probe), 0.0, 0.0);
}
)");
    std::vector<glm::vec4> io(2, glm::vec4(100000.0f, 2.0f, 0.0f, 0.0f));
    const glm::vec4 counted = kernel.run(io, 1)[1];
    const bool cut_short = counted.x < 100000.0f;
    if (cut_short) {
        EXPECT_TRUE(driver_limits_loops()) << "the driver ends loops early but lancer does not check for it";
        EXPECT_EQ(counted.x, 65535.0f);
        EXPECT_LT(counted.y, 2.0f) << "the tracer's probe would not see the cut";
    } else {
        EXPECT_EQ(counted.y, 2.0f);
    }
    if (!driver_limits_loops()) {
        EXPECT_FALSE(cut_short);
    }
}

TEST(LoopLimit, CutShortBandsAreRenderedAgainAndMatchTheReference) {
    Scene scene = test::scene_from_text(heavy_scene(300, 30));
    GpuRenderer brute(gpu::ContextOptions{"", true}, Acceleration::BruteForce);
    Rgb8Image gpu = to_srgb8(brute.render(scene, {}));
    if (driver_limits_loops())
        EXPECT_GT(brute.bands_rerendered(), 0u) << "the scene no longer exceeds the limit at 9 samples per invocation";
    else
        EXPECT_EQ(brute.bands_rerendered(), 0u);
    expect_matches_the_reference(scene, gpu);
}

TEST(LoopLimit, TooMuchWorkForOneSampleIsAClearErrorWhereTheDriverLimitsLoops) {
    Scene scene = test::scene_from_text(heavy_scene(200, 250));
    GpuRenderer brute(gpu::ContextOptions{"", true}, Acceleration::BruteForce);
    if (!driver_limits_loops()) {
        expect_matches_the_reference(scene, to_srgb8(brute.render(scene, {})));
        return;
    }
    try {
        brute.render(scene, {});
        FAIL() << "rendered a scene beyond the driver's loop limit";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("loop iterations"), std::string::npos) << e.what();
    }
}

TEST(DriverQuirks, MesaVersionsAreReadFromTheDriverInfo) {
    gpu::DeviceInfo lavapipe{0, "llvmpipe", "CPU", "llvmpipe Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)",
                             VK_DRIVER_ID_MESA_LLVMPIPE};
    EXPECT_EQ(gpu::mesa_version(lavapipe), 2500);
    EXPECT_FALSE(gpu::limits_loop_iterations(lavapipe));
    EXPECT_TRUE(gpu::keeps_device_memory_in_a_file(lavapipe));
    EXPECT_TRUE(gpu::hands_each_thread_one_run(lavapipe));
    lavapipe.driver = "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)";
    EXPECT_EQ(gpu::mesa_version(lavapipe), 2203);
    EXPECT_TRUE(gpu::limits_loop_iterations(lavapipe));
    EXPECT_FALSE(gpu::keeps_device_memory_in_a_file(lavapipe));
    lavapipe.driver = "llvmpipe";  // unknown: both rules take the safe side
    EXPECT_TRUE(gpu::limits_loop_iterations(lavapipe));
    EXPECT_TRUE(gpu::keeps_device_memory_in_a_file(lavapipe));
    gpu::DeviceInfo nvidia{0, "NVIDIA H200", "discrete GPU", "NVIDIA 570.86", VK_DRIVER_ID_NVIDIA_PROPRIETARY};
    EXPECT_FALSE(gpu::mesa_version(nvidia));
    EXPECT_FALSE(gpu::limits_loop_iterations(nvidia));
    EXPECT_FALSE(gpu::keeps_device_memory_in_a_file(nvidia));
    EXPECT_FALSE(gpu::hands_each_thread_one_run(nvidia));
}

TEST(DriverQuirks, FileBackedMemoryIsBoundedByEveryAllocationEverMade) {
    std::uint64_t allocated = 0;
    const std::uint64_t limit = 8u << 20;
    gpu::reserve_file_backed_memory(allocated, 1, limit);
    EXPECT_EQ(allocated, 4096u);  // whole pages
    gpu::reserve_file_backed_memory(allocated, 4096, limit);
    EXPECT_EQ(allocated, 8192u);
    try {
        gpu::reserve_file_backed_memory(allocated, 7u << 20, limit);
        FAIL() << "went past the file size limit";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("ulimit -f"), std::string::npos) << e.what();
    }
    EXPECT_EQ(allocated, 8192u);  // a refused allocation is not counted
    gpu::reserve_file_backed_memory(allocated, 1u << 30, kUnlimited);
}

}  // namespace
}  // namespace lancer

// Every documented limit (docs/limits.md) gives a clear error, at the place in the file that
// crosses it, before the memory it bounds is allocated. Limits of single values (image size,
// samples, max_depth, frames, subdivision, magnitudes, expression length and nesting, patch
// counts in a file) are bad files in tests/data/bad/ and tests/data/bad_patches/ and cases in
// tests/unit/expr_parser_test.cpp; here are the ones that need a scene built to size.
#include <filesystem>
#include <map>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "gpu/vulkan/memory_budget.hpp"
#include "gpu/gpu_renderer.hpp"
#include "gpu/packing/scene_packing.hpp"
#include "gpu/passes/photon_pass.hpp"
#include "gpu/vulkan/vk_check.hpp"
#include "scene/limits.hpp"
#include "scene/load_scene.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

const std::string kHead = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n";

// Parses `text` and returns "LINE:COL: message" of the SceneError it must raise.
std::string error_of(const std::string& text) {
    try {
        parse_scene(text, "limits.toml");
    } catch (const SceneError& e) {
        return fmt::format("{}:{}: {}", e.where().line, e.where().column, e.what());
    }
    return "accepted";
}

std::string repeat(const std::string& block, long long n) {
    std::string out;
    out.reserve(block.size() * static_cast<std::size_t>(n));
    for (long long i = 0; i < n; ++i) out += block;
    return out;
}

TEST(Limits, Lights) {
    const std::string light = "[[light]]\nposition = [0, 5, 0]\n";
    EXPECT_EQ(error_of(kHead + repeat(light, limits::kMaxLights)), "accepted");
    EXPECT_EQ(error_of(kHead + repeat(light, limits::kMaxLights + 1)), "4:1: too many lights (the limit is 256)");
}

TEST(Limits, Objects) {
    // As an inline array of empty tables the 1,048,576 objects take 3 MB and a fraction of a
    // second to parse. At the limit the count passes and the first object's own error comes next.
    auto objects = [](long long n) { return "object = [" + repeat("{},", n - 1) + "{}]\n" + kHead; };
    EXPECT_EQ(error_of(objects(limits::kMaxObjects)), "1:11: object 1: missing required key 'type'");
    EXPECT_EQ(error_of(objects(limits::kMaxObjects + 1)), "1:10: too many objects (the limit is 1048576)");
}

TEST(Limits, Materials) {
    std::string text = kHead;
    for (int i = 0; i <= limits::kMaxMaterials; ++i) text += fmt::format("[material.m{}]\n", i);
    EXPECT_EQ(error_of(text), "4:1: too many materials (the limit is 65536)");
}

TEST(Limits, ParametricSurfacesAreCountedBeforeTheyAreSubdivided) {
    const std::string surface = "[[object]]\ntype = \"parametric\"\nx = \"u\"\ny = \"v\"\nz = \"0\"\nu = [0, 1]\nv = [0, 1]\n";
    EXPECT_EQ(error_of(kHead + repeat(surface, limits::kMaxParametricSurfaces)), "accepted");
    int line = 4 + 7 * limits::kMaxParametricSurfaces + 1;  // the type of the one too many
    EXPECT_EQ(error_of(kHead + repeat(surface, limits::kMaxParametricSurfaces + 1)),
              fmt::format("{}:8: too many parametric surfaces (the limit is 32 per scene)", line));
}

TEST(Limits, BezierPatchesInAllObjectsTogether) {
    // The teapot's 32 patches, as many times as the limit allows, and once more.
    const std::string teapot =
        "[[object]]\ntype = \"bezier\"\nfile = \"" + test::source_path("scenes/teapot.bpt") + "\"\n";
    const long long copies = limits::kMaxPatches / 32;
    std::string text = kHead + repeat(teapot, copies);
    EXPECT_EQ(error_of(text), "accepted");
    int line = 4 + 3 * static_cast<int>(copies) + 1;
    EXPECT_EQ(error_of(text + teapot),
              fmt::format("{}:8: too many Bezier patches: 65568 so far (the limit is 65536 per scene)", line));
}

TEST(Limits, SceneFileSizeIsCheckedWhileReading) {
    // /dev/zero never ends: reading stops past the limit instead of filling the memory.
    try {
        load_scene("/dev/zero");
        FAIL() << "accepted";
    } catch (const UserError& e) {
        EXPECT_STREQ(e.what(), "cannot read scene file '/dev/zero': it is larger than the limit of 128 MiB");
    }
}

// The GPU's limits, from numbers: each scene array within maxTexelBufferElements texels, the
// output band within maxStorageBufferRange, all within the heap.
TEST(GpuMemoryBudget, NamesTheBufferTheNeedAndTheLimit) {
    Scene scene = test::scene_from_text(kHead + "[[object]]\ntype = \"bezier\"\nsubdivision = 4\nfile = \"" +
                                        test::source_path("scenes/teapot.bpt") + "\"\n");
    gpu::PackedScene packed = gpu::pack_scene(scene);
    auto needs = gpu::render_buffer_needs(packed, 1 << 20);
    auto leaves = std::find_if(needs.begin(), needs.end(), [](const auto& n) { return n.what == "Bezier patch leaves"; });
    ASSERT_NE(leaves, needs.end());
    EXPECT_EQ(leaves->count, 32u * 256u);
    EXPECT_EQ(leaves->bytes, 32u * 256u * sizeof(gpu::PatchLeaf));
    EXPECT_NO_THROW(gpu::check_memory_budget(needs, {"big GPU", 1u << 27, 1ull << 30, 8ull << 30}));
    try {
        gpu::check_memory_budget(needs, {"tiny GPU", 1u << 16, 1ull << 30, 8ull << 30});
        FAIL() << "accepted";
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("the scene needs 2 MiB of GPU memory for its Bezier patch leaves (8192 of "
                                              "them), more than tiny GPU allows in one buffer, 1 MiB (65536 texels of 16 "
                                              "bytes, maxTexelBufferElements)",
                                              0),
                  0u)
            << e.what();
    }
    try {
        gpu::check_memory_budget(needs, {"narrow GPU", 1u << 27, 1u << 19, 8ull << 30});
        FAIL() << "accepted";
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("the scene needs 1 MiB of GPU memory for its output rows (65536 of them), "
                                              "more than narrow GPU allows in one buffer, 524288 bytes "
                                              "(maxStorageBufferRange)",
                                              0),
                  0u)
            << e.what();
    }
    try {
        gpu::check_memory_budget(needs, {"small GPU", 1u << 27, 1ull << 30, 3 << 20});
        FAIL() << "accepted";
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("the scene needs 5 MiB of GPU memory in all, more than small GPU has "
                                              "(3 MiB in its memory heap)", 0),
                  0u)
            << e.what();
    }
}

// The budget is what the packer made: one entry per scene array of the interface, its size the
// packed array's, then the output band and the list of pixels to refine (adaptive anti-aliasing),
// then (photon-mapped scenes) every buffer of the photon pass, as the pass allocates them.
TEST(GpuMemoryBudget, IsThePackedArraysSizes) {
    for (const std::string& path : test::scene_files()) {
        gpu::PackedScene packed = gpu::pack_scene(load_scene(path), {Acceleration::BvhAlways});
        auto needs = gpu::render_buffer_needs(packed, 64);
        const std::size_t photon_buffers =
            packed.features.has_photons ? gpu::PhotonPass::buffer_needs(gpu::photon_capacity(packed.photon_count)).size() : 0;
        ASSERT_EQ(needs.size(), gpu::kSceneArrayCount + 2 + photon_buffers) << path;
        for (std::size_t a = 0; a < gpu::kSceneArrayCount; ++a) {
            EXPECT_EQ(needs[a].what, gpu::kSceneArrays[a].what);
            EXPECT_EQ(needs[a].bytes, packed.bytes(gpu::SceneArray(a)).size()) << path << ": " << needs[a].what;
        }
        EXPECT_EQ(needs[gpu::kSceneArrayCount].bytes, 64u) << path;  // the output band: 4 pixels
        EXPECT_EQ(needs[gpu::kSceneArrayCount + 1].what, "pixels to refine");  // at most those 4, one uint each
        EXPECT_EQ(needs[gpu::kSceneArrayCount + 1].bytes, 16u);
        for (std::size_t b = 0; b < photon_buffers; ++b)
            EXPECT_GT(needs[gpu::kSceneArrayCount + 2 + b].bytes, 0u) << path << ": " << needs[gpu::kSceneArrayCount + 2 + b].what;
    }
}

// The photon pass's copies for the tracer's gather are texel buffers: a capacity beyond the
// device's maxTexelBufferElements for them is refused, naming them, though every storage buffer
// would hold it.
TEST(GpuMemoryBudget, PhotonGatherCopiesAreCheckedAsTexelBuffers) {
    const std::vector<gpu::BufferNeed> needs = gpu::PhotonPass::buffer_needs(1u << 20);
    const auto gather = std::find_if(needs.begin(), needs.end(), [](const auto& n) { return n.binding == gpu::BINDING_GATHER_PHOTONS; });
    ASSERT_NE(gather, needs.end());
    EXPECT_EQ(gather->count, 1u << 20);
    const gpu::DeviceMemoryLimits few_texels{"small GPU", (1u << 20) * gpu::Photon_ROWS - 1, 1ull << 40, 1ull << 40};
    EXPECT_FALSE(gpu::fits(*gather, few_texels));
    try {
        gpu::check_memory_budget(needs, few_texels);
        FAIL() << "accepted";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("photons to gather"), std::string::npos) << e.what();
    }
}

// End to end on this machine's device: patch leaves beyond maxTexelBufferElements (lavapipe:
// 2^27 texels, 2 GiB) are refused before they are made, with exit code 2 and no output. 911
// teapots at subdivision 4 are 7.5 million leaves of 18 texels.
TEST(GpuMemoryBudget, ASceneTooLargeForTheDeviceIsAClearError) {
    std::string scene = test::output_dir() + "/limits-gpu-memory.toml";
    std::string out = test::output_dir() + "/limits-gpu-memory.png";
    std::filesystem::remove(out);
    const std::string teapot = "[[object]]\ntype = \"bezier\"\nsubdivision = 4\nfile = \"" +
                               test::source_path("scenes/teapot.bpt") + "\"\n";
    test::write_file(scene, kHead + repeat(teapot, 911));
    auto r = test::run_lancer("render " + scene + " --width 8 --height 8 -o " + out);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("lancer: error: the scene needs 2.0 GiB of GPU memory for its Bezier patch leaves (7462912 of "
                          "them), more than ",
                          0),
              0u)
        << r.err;
    EXPECT_NE(r.err.find("maxTexelBufferElements"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line, no validation message: " << r.err;
    EXPECT_FALSE(test::file_exists(out));
}

// What the driver reports becomes an error that says what happened and what to do.
TEST(VulkanErrors, OutOfMemoryIsAUserErrorAndDeviceLossSaysSo) {
    try {
        gpu::throw_vulkan_error(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory(...)", "/x/buffer.cpp", 30);
    } catch (const gpu::GpuOutOfMemory& e) {
        EXPECT_STREQ(e.what(), "the GPU ran out of memory (Vulkan call failed with VK_ERROR_OUT_OF_DEVICE_MEMORY: "
                               "vkAllocateMemory(...) (buffer.cpp:30)): render a smaller image or a smaller scene, or "
                               "with --backend cpu");
    }
    EXPECT_THROW(gpu::throw_vulkan_error(VK_ERROR_OUT_OF_HOST_MEMORY, "vkCreateBuffer", "b.cpp", 1), UserError);
    try {
        gpu::throw_vulkan_error(VK_ERROR_DEVICE_LOST, "vkWaitForFences(...)", "gpu_renderer.cpp", 240);
        FAIL();
    } catch (const gpu::VulkanError& e) {
        EXPECT_EQ(e.result(), VK_ERROR_DEVICE_LOST);
        EXPECT_STREQ(e.what(), "Vulkan call failed with VK_ERROR_DEVICE_LOST: vkWaitForFences(...) (gpu_renderer.cpp:240); "
                               "the GPU driver reset or crashed (device lost)");
    }
}

}  // namespace
}  // namespace lancer

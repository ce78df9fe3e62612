// The run-time compile path (glslang library, used by hot reload and expression surfaces) and
// the build-time SPIR-V embedded in the binary take the same sources and defines, so they must
// render identical images.
#include <gtest/gtest.h>

#include "gpu/shaders/embedded_shaders.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

TEST(RuntimeCompile, EmbeddedSourcesMatchEmbeddedSpirv) {
    Scene scene = test::shipped_scene("seed", 96, 54);
    GpuRenderer& renderer = test::gpu_renderer();
    Rgb8Image build_time = to_srgb8(renderer.render(scene, {}));
    renderer.use_shaders(gpu::embedded_tree());
    Rgb8Image run_time = to_srgb8(renderer.render(scene, {}));
    EXPECT_EQ(build_time.bytes, run_time.bytes);
}

TEST(RuntimeCompile, EmbeddedSourcesAreTheSourceTree) {
    auto disk = gpu::directory_tree(test::source_path("shaders"));
    for (const auto& [name, text] : gpu::embedded_shader_files()) EXPECT_EQ(disk(name), text) << name;
    EXPECT_TRUE(gpu::embedded_shader_files().count("trace.comp"));
}

TEST(RuntimeCompile, ErrorsNameTheFileAndLine) {
    auto tree = [](const std::string& name) -> std::optional<std::string> {
        if (name == "trace.comp") return std::string(
            "#version 450\n#extension GL_GOOGLE_include_directive : require\n#include \"broken.glsl\"\n"
            "layout(local_size_x = 1) in;\nvoid main() {}\n");
        if (name == "broken.glsl") return std::string("// fine\nfloat f() { return undefined_thing; }\n");
        return std::nullopt;
    };
    try {
        gpu::compile_compute(tree, "trace.comp");
        FAIL() << "compiled a broken shader";
    } catch (const gpu::ShaderCompileError& e) {
        EXPECT_NE(std::string(e.what()).find("broken.glsl:2"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lancer

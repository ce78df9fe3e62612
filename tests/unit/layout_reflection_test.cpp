// The host's structs (shaders/layout.h compiled as C++) must match what glslang lays out for the
// shader: every member offset of every block, taken from glslang's reflection of trace.comp.
#include <cstddef>
#include <map>

#include <gtest/gtest.h>

#include "gpu/layout.hpp"
#include "gpu/shader_compiler.hpp"
#include "support/test_support.hpp"

namespace lancer::gpu {
namespace {

std::map<std::string, int> reflected(bool strides = false) {
    std::map<std::string, int> values;
    for (const auto& m : reflect_block_members(directory_tree(test::source_path("shaders")), "trace.comp"))
        values[m.name] = strides ? m.top_level_stride : m.offset;
    return values;
}

#define EXPECT_OFFSET(block_member, type, member) \
    do {                                                                                 \
        auto found = offsets.find(block_member);                                         \
        ASSERT_NE(found, offsets.end()) << "glslang does not reflect " << block_member;   \
        EXPECT_EQ(found->second, static_cast<int>(offsetof(type, member))) << block_member; \
        ++checked;                                                                       \
    } while (0)

TEST(Layout, HostOffsetsMatchGlslangReflection) {
    auto offsets = reflected();
    int checked = 0;
    EXPECT_OFFSET("frame.eye", FrameParams, eye);
    EXPECT_OFFSET("frame.forward", FrameParams, forward);
    EXPECT_OFFSET("frame.right", FrameParams, right);
    EXPECT_OFFSET("frame.up", FrameParams, up);
    EXPECT_OFFSET("frame.background", FrameParams, background);
    EXPECT_OFFSET("frame.ambient", FrameParams, ambient);
    EXPECT_OFFSET("frame.width", FrameParams, width);
    EXPECT_OFFSET("frame.height", FrameParams, height);
    EXPECT_OFFSET("frame.samples", FrameParams, samples);
    EXPECT_OFFSET("frame.max_depth", FrameParams, max_depth);
    EXPECT_OFFSET("frame.primitive_count", FrameParams, primitive_count);
    EXPECT_OFFSET("frame.light_count", FrameParams, light_count);
    EXPECT_OFFSET("primitives.type", Primitive, type);
    EXPECT_OFFSET("primitives.material", Primitive, material);
    EXPECT_OFFSET("primitives.p0", Primitive, p0);
    EXPECT_OFFSET("primitives.p1", Primitive, p1);
    EXPECT_OFFSET("primitives.p2", Primitive, p2);
    EXPECT_OFFSET("materials.color", Material, color);
    EXPECT_OFFSET("materials.color2", Material, color2);
    EXPECT_OFFSET("materials.phong", Material, phong);
    EXPECT_OFFSET("materials.reflection", Material, reflection);
    EXPECT_OFFSET("materials.pattern", Material, pattern);
    EXPECT_OFFSET("materials.checker_size", Material, checker_size);
    EXPECT_OFFSET("lights.position", Light, position);
    EXPECT_OFFSET("lights.color", Light, color);
    EXPECT_OFFSET("band.y0", BandParams, y0);
    EXPECT_OFFSET("band.rows", BandParams, rows);
    EXPECT_OFFSET("band.sample_first", BandParams, sample_first);
    EXPECT_OFFSET("band.sample_count", BandParams, sample_count);
    EXPECT_GT(checked, 0);
}

TEST(Layout, ArrayStridesMatchHostSizes) {
    auto strides = reflected(/*strides=*/true);
    EXPECT_EQ(strides.at("primitives.p0"), static_cast<int>(sizeof(Primitive)));
    EXPECT_EQ(strides.at("materials.color"), static_cast<int>(sizeof(Material)));
    EXPECT_EQ(strides.at("lights.color"), static_cast<int>(sizeof(Light)));
}

}  // namespace
}  // namespace lancer::gpu

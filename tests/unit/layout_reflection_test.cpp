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

// The shaders, with a parametric surface compiled in, so the blocks only its code uses are
// reflected too.
ShaderTree full_tree() {
    auto disk = directory_tree(test::source_path("shaders"));
    return [disk](const std::string& name) -> std::optional<std::string> {
        if (name == "surface_functions.glsl")
            return std::string("#define LANCER_PARAMETRIC_SURFACES 1\n"
                               "void surface_eval(uint s, vec2 uv, out vec3 P, out vec3 Pu, out vec3 Pv) {\n"
                               "    P = vec3(uv, 0.0); Pu = vec3(1.0, 0.0, 0.0); Pv = vec3(0.0, 1.0, 0.0);\n}\n");
        return disk(name);
    };
}

std::map<std::string, int> reflected(bool strides = false) {
    std::map<std::string, int> values;
    for (const auto& m : reflect_block_members(full_tree(), "trace.comp"))
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
    EXPECT_OFFSET("frame.node_count", FrameParams, node_count);
    EXPECT_OFFSET("frame.unbounded_count", FrameParams, unbounded_count);
    EXPECT_OFFSET("frame.loop_probe", FrameParams, loop_probe);
    EXPECT_OFFSET("primitives.type", Primitive, type);
    EXPECT_OFFSET("primitives.material", Primitive, material);
    EXPECT_OFFSET("primitives.p0", Primitive, p0);
    EXPECT_OFFSET("primitives.p1", Primitive, p1);
    EXPECT_OFFSET("primitives.p2", Primitive, p2);
    EXPECT_OFFSET("primitives.data", Primitive, data);
    EXPECT_OFFSET("primitives.object", Primitive, object);
    EXPECT_OFFSET("nodes.lo", BvhNode, lo);
    EXPECT_OFFSET("nodes.hi", BvhNode, hi);
    EXPECT_OFFSET("nodes.first", BvhNode, first);
    EXPECT_OFFSET("nodes.count", BvhNode, count);
    EXPECT_OFFSET("patch_leaves.points", PatchLeaf, points);
    EXPECT_OFFSET("patch_leaves.origin", PatchLeaf, origin);
    EXPECT_OFFSET("patch_leaves.domain", PatchLeaf, domain);
    EXPECT_OFFSET("surfaces.row0", SurfaceInfo, row0);
    EXPECT_OFFSET("surfaces.row1", SurfaceInfo, row1);
    EXPECT_OFFSET("surfaces.row2", SurfaceInfo, row2);
    EXPECT_OFFSET("surfaces.domain", SurfaceInfo, domain);
    EXPECT_OFFSET("cells.domain", ParametricCell, domain);
    EXPECT_OFFSET("cells.p00", ParametricCell, p00);
    EXPECT_OFFSET("cells.p10", ParametricCell, p10);
    EXPECT_OFFSET("cells.p01", ParametricCell, p01);
    EXPECT_OFFSET("cells.p11", ParametricCell, p11);
    EXPECT_OFFSET("materials.color", Material, color);
    EXPECT_OFFSET("materials.color2", Material, color2);
    EXPECT_OFFSET("materials.phong", Material, phong);
    EXPECT_OFFSET("materials.reflection", Material, reflection);
    EXPECT_OFFSET("materials.pattern", Material, pattern);
    EXPECT_OFFSET("materials.checker_size", Material, checker_size);
    EXPECT_OFFSET("materials.texture_map", Material, texture_map);
    EXPECT_OFFSET("materials.color_pattern", Material, color_pattern);
    EXPECT_OFFSET("materials.bump_pattern", Material, bump_pattern);
    EXPECT_OFFSET("materials.transmission", Material, transmission);
    EXPECT_OFFSET("materials.absorption", Material, absorption);
    EXPECT_OFFSET("materials.highlight", Material, highlight);
    EXPECT_OFFSET("textures.to_image_s", TextureInfo, to_image_s);
    EXPECT_OFFSET("textures.to_image_t", TextureInfo, to_image_t);
    EXPECT_OFFSET("textures.texel_offset", TextureInfo, texel_offset);
    EXPECT_OFFSET("textures.width", TextureInfo, width);
    EXPECT_OFFSET("textures.height", TextureInfo, height);
    EXPECT_OFFSET("textures.flags", TextureInfo, flags);
    EXPECT_OFFSET("patterns.row0", PatternInfo, row0);
    EXPECT_OFFSET("patterns.row1", PatternInfo, row1);
    EXPECT_OFFSET("patterns.row2", PatternInfo, row2);
    EXPECT_OFFSET("patterns.params", PatternInfo, params);
    EXPECT_OFFSET("patterns.type", PatternInfo, type);
    EXPECT_OFFSET("patterns.octaves", PatternInfo, octaves);
    EXPECT_OFFSET("patterns.color_count", PatternInfo, color_count);
    EXPECT_OFFSET("patterns.colors", PatternInfo, colors);
    EXPECT_OFFSET("lights.position", Light, position);
    EXPECT_OFFSET("lights.color", Light, color);
    EXPECT_OFFSET("lights.direction", Light, direction);
    EXPECT_OFFSET("lights.spot", Light, spot);
    EXPECT_OFFSET("lights.edge_u", Light, edge_u);
    EXPECT_OFFSET("lights.edge_v", Light, edge_v);
    EXPECT_OFFSET("lights.type", Light, type);
    EXPECT_OFFSET("lights.samples", Light, samples);
    EXPECT_OFFSET("lights.jitter", Light, jitter);
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
    EXPECT_EQ(strides.at("nodes.lo"), static_cast<int>(sizeof(BvhNode)));
    EXPECT_EQ(strides.at("patch_leaves.origin"), static_cast<int>(sizeof(PatchLeaf)));
    EXPECT_EQ(strides.at("surfaces.row0"), static_cast<int>(sizeof(SurfaceInfo)));
    EXPECT_EQ(strides.at("cells.p00"), static_cast<int>(sizeof(ParametricCell)));
    EXPECT_EQ(strides.at("textures.flags"), static_cast<int>(sizeof(TextureInfo)));
    EXPECT_EQ(strides.at("patterns.colors"), static_cast<int>(sizeof(PatternInfo)));
    EXPECT_EQ(strides.at("texels"), static_cast<int>(sizeof(uint)));
    EXPECT_EQ(strides.at("perlin_permutation"), static_cast<int>(sizeof(int)));
}

// Every block the shader declares sits at the binding layout.h names for it (the host binds
// its buffers by those names), and every binding is used.
TEST(Layout, BlockBindingsAreLayoutConstants) {
    const std::map<std::string, int> expected = {
        {"FrameBlock", int(BINDING_FRAME)},         {"PrimitiveBlock", int(BINDING_PRIMITIVES)},
        {"MaterialBlock", int(BINDING_MATERIALS)},  {"LightBlock", int(BINDING_LIGHTS)},
        {"OutputBlock", int(BINDING_OUTPUT)},       {"NodeBlock", int(BINDING_NODES)},
        {"PatchBlock", int(BINDING_PATCHES)},       {"SurfaceBlock", int(BINDING_SURFACES)},
        {"CellBlock", int(BINDING_CELLS)},          {"TextureBlock", int(BINDING_TEXTURES)},
        {"TexelBlock", int(BINDING_TEXELS)},        {"PatternBlock", int(BINDING_PATTERNS)},
        {"PermutationBlock", int(BINDING_PERMUTATION)},
        {"BandBlock", -1}};  // push constants: no binding
    EXPECT_EQ(reflect_block_bindings(full_tree(), "trace.comp"), expected);
}

}  // namespace
}  // namespace lancer::gpu

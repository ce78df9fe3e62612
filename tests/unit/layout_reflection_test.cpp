// The host's view of the interface (shaders/layout.h compiled as C++) must be what glslang makes
// of the shader: every member of every block it reflects at the host's offset, every member the
// host has reflected, and every descriptor of LANCER_RESOURCES declared at its binding with the
// type its kind means. Nothing here lists members or bindings by hand: a member or resource added
// to layout.h is checked at once. The tracer, photon mapping's two compute passes and adaptive
// anti-aliasing's selection share the one table, so the checks run over all four entry points.
// (Structs read from texel buffers have no block to reflect:
// tests/render/interface_test.cpp reads each back through the shader instead.)
#include <cstddef>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "gpu/layout.hpp"
#include "gpu/shaders/shader_compiler.hpp"
#include "support/test_support.hpp"

namespace lancer::gpu {
namespace {

// The shaders, with a parametric surface compiled in, so the resources only its code uses are
// reflected too.
ShaderTree full_tree() {
    auto disk = directory_tree(test::source_path("shaders"));
    return [disk](const std::string& name) -> std::optional<std::string> {
        if (name == "surface_functions.glsl")
            return std::string("#define LANCER_PARAMETRIC_SURFACES 1\n"
                               "void surface_eval(uint s, vec2 uv, out vec3 P, out vec3 Pu, out vec3 Pv) {\n"
                               "    P = vec3(uv, 0.0); Pu = vec3(1.0, 0.0, 0.0); Pv = vec3(0.0, 1.0, 0.0);\n}\n"
                               "#define LANCER_IMPLICIT_SURFACES 1\n#include \"interval.glsl\"\n"
                               "float implicit_eval(uint s, vec3 p, vec3 d, out float df) { df = dot(p, d); return dot(p, p) - 1.0; }\n"
                               "vec3 implicit_gradient(uint s, vec3 p) { return p; }\n"
                               "void implicit_interval(uint s, vec3 o, vec3 d, vec2 t, out vec2 f, out vec2 df) {\n"
                               "    f = vec2(t.x - 1.0, t.y); df = vec2(1.0);\n}\n");
        return disk(name);
    };
}

// Member name -> offset in the C++ struct, from the struct's row list.
using Offsets = std::map<std::string, std::size_t>;
#define OFFSET_VEC4(name) {#name, offsetof(S, name)},
#define OFFSET_VEC4S(name, n) {#name, offsetof(S, name)},
#define OFFSET_UVEC4S(name, n) {#name, offsetof(S, name)},
#define OFFSET_SCALARS(T0, n0, T1, n1, T2, n2, T3, n3) \
    {#n0, offsetof(S, n0)}, {#n1, offsetof(S, n1)}, {#n2, offsetof(S, n2)}, {#n3, offsetof(S, n3)},
#define HOST_OFFSETS(Name)                                                          \
    [] {                                                                             \
        using S = Name;                                                              \
        return Offsets{LANCER_ROWS_##Name(OFFSET_VEC4, OFFSET_VEC4S, OFFSET_SCALARS, OFFSET_UVEC4S)}; \
    }()

// The block variables of the shader, by their name in glslang's reflection, and the host struct
// each holds (an array of vec4 has the one member "", at offset 0).
struct BlockVariable {
    Offsets members;
    int stride;  // of a runtime-sized array, else 0
};
std::map<std::string, BlockVariable> host_block_variables() {
    const Offsets uints{{"", 0}};
    return {{"frame", {HOST_OFFSETS(FrameParams), 0}},
            {"band", {HOST_OFFSETS(BandParams), 0}},
            {"pixels", {Offsets{{"", 0}}, int(sizeof(vec4))}},
            {"photon_params", {HOST_OFFSETS(PhotonParams), 0}},
            {"step", {HOST_OFFSETS(GridStep), 0}},
            {"photons", {HOST_OFFSETS(Photon), int(sizeof(Photon))}},
            {"photons_sorted", {HOST_OFFSETS(Photon), int(sizeof(Photon))}},
            {"photon_counter", {uints, int(sizeof(uint))}},
            {"cell_count", {uints, int(sizeof(uint))}},
            {"cell_start", {uints, int(sizeof(uint))}},
            {"block_sums", {uints, int(sizeof(uint))}},
            {"selection", {HOST_OFFSETS(SelectStep), 0}},
            {"refine_list", {uints, int(sizeof(uint))}},
            {"picture", {Offsets{{"", 0}}, int(sizeof(vec4))}},
            {"picture_codes", {uints, int(sizeof(uint))}},
            {"refine_flags", {uints, int(sizeof(uint))}}};
}

// The compute entry points that share the resource table.
const char* const kEntries[] = {"trace.comp", "photons.comp", "photon_grid.comp", "refine_select.comp"};

TEST(Layout, EveryReflectedBlockMemberIsAtTheHostsOffsetAndEveryHostMemberIsReflected) {
    const auto host = host_block_variables();
    std::set<std::string> seen;
    for (const char* entry : kEntries) {
        for (const ReflectedMember& m : reflect_block_members(full_tree(), entry)) {
            // An array of structs is reflected through its first element: "photons[0].power".
            std::string variable = m.name.substr(0, m.name.find('.'));
            if (variable.size() > 3 && variable.compare(variable.size() - 3, 3, "[0]") == 0) variable.resize(variable.size() - 3);
            const std::string member = m.name.find('.') == std::string::npos ? "" : m.name.substr(m.name.find('.') + 1);
            auto block = host.find(variable);
            ASSERT_NE(block, host.end()) << entry << " has a block variable the host does not know: " << m.name;
            auto offset = block->second.members.find(member);
            ASSERT_NE(offset, block->second.members.end()) << "the host's struct has no member " << m.name;
            EXPECT_EQ(m.offset, static_cast<int>(offset->second)) << m.name;
            if (block->second.stride) { EXPECT_EQ(m.top_level_stride, block->second.stride) << m.name; }
            seen.insert(variable + "." + member);
        }
    }
    for (const auto& [variable, block] : host)
        for (const auto& [member, offset] : block.members)
            EXPECT_TRUE(seen.count(variable + "." + member)) << "glslang does not reflect " << variable << "." << member;
}

// What a resource kind must look like in the shader.
std::string reflected_kind(uint kind) {
    switch (kind) {
        case RESOURCE_UNIFORM: return "uniform block";
        case RESOURCE_OUTPUT: return "storage block";
        case RESOURCE_ROWS:
        case RESOURCE_UINT: return "uint texel buffer";
        case RESOURCE_INT: return "int texel buffer";
    }
    return "unknown kind";
}

TEST(Layout, EveryResourceIsDeclaredAtItsBindingWithItsKindAndNothingElse) {
    std::map<std::string, std::pair<std::string, int>> expected;
    for (const ResourceSpec& r : kResources) {
        const std::string kind = reflected_kind(r.kind);
        const std::string suffix = kind.find("texel") != std::string::npos ? "_texels" : "_Block";
        expected[std::string(r.name) + suffix] = {kind, int(r.binding)};
    }
    expected["BandBlock"] = {"push constants", -1};
    expected["GridBlock"] = {"push constants", -1};
    expected["SelectBlock"] = {"push constants", -1};
    // Each entry point declares a part of the table; together they declare all of it.
    std::map<std::string, std::pair<std::string, int>> declared;
    for (const char* entry : kEntries)
        for (const ReflectedResource& r : reflect_resources(full_tree(), entry)) {
            auto at = declared.emplace(r.name, std::pair{r.kind, r.binding}).first;
            EXPECT_EQ(at->second, (std::pair{r.kind, r.binding})) << entry << " declares " << r.name << " differently";
        }
    EXPECT_EQ(declared, expected);
}

// Every row list adds up to its struct's size (also static_asserted), and texel-buffer
// elements are whole texels.
TEST(Layout, ResourceElementsAreWholeTexels) {
    for (const ResourceSpec& r : kResources) {
        if (!texel_bytes(r.kind)) continue;
        EXPECT_EQ(r.element_bytes % texel_bytes(r.kind), 0u) << r.name;
    }
}

}  // namespace
}  // namespace lancer::gpu

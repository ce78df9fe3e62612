// The tracer and photon pass built for fewer shape types (shapes.h's CHEAP_SHAPE_TYPES and
// COMMON_SHAPE_TYPES, pruned at build time by gpu/shaders/spirv_prune, the tracer's locals made
// SSA values there): every shipped scene that one of them serves gets from it, once specialised,
// the very program the whole module gives through the same steps (the same instructions once
// SPIRV-Tools has simplified both to the end, only numbered apart), and every other scene gets
// the whole module.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <spirv-tools/optimizer.hpp>

#include "gpu/packing/scene_packing.hpp"
#include "gpu/shaders/embedded_shaders.hpp"
#include "gpu/shaders/shader_compiler.hpp"
#include "gpu/shaders/spirv_passes.hpp"
#include "gpu/shaders/spirv_prune.hpp"
#include "gpu/shaders/spirv_specialize.hpp"
#include "scene/load_scene.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// The module simplified until SPIRV-Tools' passes change it no more (dead code, local variables,
// constants, unused interface variables) and its ids renumbered in order of appearance: equal for
// two modules that hold the same program, whatever cleanup each had. (lancer's specialisation
// stops after two rounds of dead-code removal, and a module pruned at build time has had more: the
// photon pass of a scene without meshes keeps the meshes' code from the whole module, not from
// the cheap one.)
std::vector<std::uint32_t> canonical(const std::vector<std::uint32_t>& spirv) {
    std::vector<std::uint32_t> module = spirv;
    for (int round = 0; round < 8; ++round) {
        spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2);
        gpu::add_dead_code_rounds(optimizer, 1);
        EXPECT_TRUE(optimizer.RegisterPassesFromFlags(gpu::kLocalVariablePasses));
        EXPECT_TRUE(optimizer.RegisterPassesFromFlags(gpu::kConstantPasses));
        EXPECT_TRUE(optimizer.RegisterPassesFromFlags({"--remove-unused-interface-variables"}));
        std::vector<std::uint32_t> out;
        EXPECT_TRUE(optimizer.Run(module.data(), module.size(), &out));
        if (out == module) break;
        module = std::move(out);
    }
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2);
    optimizer.RegisterPass(spvtools::CreateCompactIdsPass());
    std::vector<std::uint32_t> out;
    EXPECT_TRUE(optimizer.Run(module.data(), module.size(), &out));
    return out;
}

// What lancer specialises on lavapipe (whose loop limit the tracer checks).
gpu::ShaderFeatures features_of(const std::string& path) {
    gpu::ShaderFeatures features = gpu::pack_scene(load_scene(path)).features;
    features.check_loop_limit = true;
    return features;
}

class TraceModules : public testing::TestWithParam<std::string> {};

// The tracer for every scene; the photon pass, which carries the same shape code, for the scenes
// that shoot photons.
TEST_P(TraceModules, ASceneGetsTheWholeProgramFromTheModuleChosenForIt) {
    const gpu::ShaderFeatures features = features_of(GetParam());
    const bool photons = test::read_file(GetParam()).find("\n[photons]") != std::string::npos;
    for (const char* entry : {gpu::kTraceShader, gpu::kPhotonShader}) {
        if (entry == gpu::kPhotonShader && !photons) continue;
        SCOPED_TRACE(entry);
        const std::vector<std::uint32_t> whole = gpu::embedded_spirv(entry);
        const gpu::EmbeddedModule chosen = gpu::embedded_module(entry, features);
        if (!gpu::traces_only(features, COMMON_SHAPE_TYPES)) {
            EXPECT_EQ(chosen.spirv, whole) << "a scene of other shapes takes the whole program";
            EXPECT_FALSE(chosen.locals_in_ssa);
            continue;
        }
        EXPECT_LT(chosen.spirv.size(), whole.size());
        EXPECT_EQ(chosen.locals_in_ssa, entry == gpu::kTraceShader) << "the tracer's locals became SSA values at build time";
        // As lancer specialises each (gpu_renderer.cpp, photon_pass.cpp).
        const auto cleanup = [&](bool locals_in_ssa) {
            return entry == gpu::kTraceShader ? gpu::spirv_cleanup_for(features, locals_in_ssa) : gpu::SpirvCleanup::dead_code;
        };
        // The whole module through the same build-time steps: the pruning of a whole module
        // folds no shape flag, and leaves its locals as SSA values where the chosen one's are.
        const std::vector<std::uint32_t> whole_built = gpu::prune_spirv(whole, chosen.locals_in_ssa);
        EXPECT_EQ(canonical(gpu::specialize_spirv(chosen.spirv, features, cleanup(chosen.locals_in_ssa))),
                  canonical(gpu::specialize_spirv(whole_built, features, cleanup(chosen.locals_in_ssa))));
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, TraceModules, testing::ValuesIn(test::scene_files()), [](const auto& info) {
    return std::filesystem::path(info.param).stem().string();
});

TEST(TraceModuleChoice, TheSmallestModuleThatHasEveryShapeOfTheScene) {
    gpu::ShaderFeatures spheres;
    spheres.add_shape(SHAPE_SPHERE);
    spheres.add_shape(SHAPE_PLANE);
    gpu::ShaderFeatures torus = spheres;
    torus.add_shape(SHAPE_TORUS);
    gpu::ShaderFeatures csg = spheres;
    csg.add_shape(SHAPE_CSG);
    const std::size_t cheap = gpu::embedded_module(gpu::kTraceShader, spheres).spirv.size();
    const std::size_t common = gpu::embedded_module(gpu::kTraceShader, torus).spirv.size();
    const std::size_t whole = gpu::embedded_trace_spirv().size();
    EXPECT_LT(cheap, common);
    EXPECT_LT(common, whole);
    EXPECT_EQ(gpu::embedded_module(gpu::kTraceShader, csg).spirv.size(), whole);
    // A family outside the BVH is one of the scene's too, and a CSG leaf's type may be no
    // primitive's of its own: either set beyond the module's types takes a larger module.
    gpu::ShaderFeatures boxed = spheres;
    boxed.boxed_families |= 1u << SHAPE_TORUS;
    EXPECT_EQ(gpu::embedded_module(gpu::kTraceShader, boxed).spirv.size(), common);
    gpu::ShaderFeatures leaf = spheres;
    leaf.csg_leaf_shapes |= 1u << SHAPE_LATHE;
    EXPECT_EQ(gpu::embedded_module(gpu::kTraceShader, leaf).spirv.size(), whole);
}

// A module whose shape flag folds to false: the branch it guards goes, the other stays.
TEST(SpirvPrune, FoldsATestOfAConstantAgainstAZeroMaskAndRemovesWhatItGuarded) {
    const std::string glsl = R"(#version 450
layout(local_size_x = 1) in;
layout(constant_id = 0) const uint SHAPES = 0xffffffffu;
const uint BUILT = 2u;
const bool HAS_A = (SHAPES & (BUILT & 1u)) != 0u;
const bool HAS_B = (SHAPES & (BUILT & 2u)) != 0u;
layout(set = 0, binding = 0) buffer Out { float x[]; };
void a() { x[0] = 1234.5; }
void main() { if (HAS_A && x[2] > 0.0) a(); if (HAS_B) x[1] = 2.0; }
)";
    const std::vector<std::uint32_t> module = gpu::compile_compute(
        [&](const std::string& name) { return name == "t.comp" ? std::optional<std::string>(glsl) : std::nullopt; },
        "t.comp");
    const std::vector<std::uint32_t> pruned = gpu::prune_spirv(module);
    const auto has_constant = [](const std::vector<std::uint32_t>& words, float value) {
        std::uint32_t bits;
        std::memcpy(&bits, &value, 4);
        return std::find(words.begin() + 5, words.end(), bits) != words.end();
    };
    EXPECT_TRUE(has_constant(module, 1234.5f));
    EXPECT_FALSE(has_constant(pruned, 1234.5f)) << "a() is gone with its call";
    EXPECT_TRUE(has_constant(pruned, 2.0f)) << "HAS_B's branch stays: a specialisation constant decides it";
    EXPECT_THROW(gpu::prune_spirv({1, 2, 3}), std::runtime_error);
}

}  // namespace
}  // namespace lancer

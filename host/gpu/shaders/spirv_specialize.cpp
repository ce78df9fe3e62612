#include "gpu/shaders/spirv_specialize.hpp"

#include <string>
#include <unordered_map>
#include <vector>

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include "gpu/shaders/spirv_dead_code.hpp"

namespace lancer::gpu {

namespace {

// SPIRV-Tools' performance recipe (spirv-opt -O) without the passes measured to cost lavapipe's
// JIT code (inlining and merge-return: lavapipe inlines itself, and the merged returns become
// loops; scalar replacement; if-conversion) and without --simplify-instructions, whose folding
// of OpCompositeInserts gave a struct of the wrong (structurally equal) type in SPIRV-Tools
// 2022.4 (an invalid module for the BVH tracer). `spirv-opt` with these flags reproduces it.
const std::vector<std::string> kLocalVariablePasses = {
    "--private-to-local", "--eliminate-local-single-block", "--eliminate-local-single-store",
    "--eliminate-dead-code-aggressive", "--convert-local-access-chains", "--eliminate-local-single-block",
    "--eliminate-local-single-store", "--eliminate-dead-code-aggressive", "--ssa-rewrite",
    "--eliminate-dead-code-aggressive", "--ccp", "--eliminate-dead-branches", "--redundancy-elimination",
    "--combine-access-chains", "--convert-local-access-chains", "--eliminate-local-single-block",
    "--eliminate-local-single-store", "--eliminate-dead-code-aggressive", "--ssa-rewrite",
    "--eliminate-dead-code-aggressive", "--vector-dce", "--eliminate-dead-inserts", "--eliminate-dead-branches",
    "--copy-propagate-arrays", "--reduce-load-size", "--eliminate-dead-code-aggressive", "--merge-blocks",
    "--redundancy-elimination", "--eliminate-dead-branches", "--merge-blocks"};

}  // namespace

std::string spirv_recipe(SpirvCleanup cleanup) {
    std::string recipe = "specialise; 2 x (dead branches, dead code, dead functions, merge blocks)";
    if (cleanup == SpirvCleanup::local_variables)
        for (const std::string& flag : kLocalVariablePasses) recipe += " " + flag;
    return recipe;
}

SpirvCleanup spirv_cleanup_for(const ShaderFeatures& features) {
    for (uint type = 0; type < SHAPE_COUNT; ++type)
        if (features.has_shape(type) && shape_has(type, SHAPE_KEEPS_LOCALS)) return SpirvCleanup::dead_code;
    return SpirvCleanup::local_variables;
}

std::vector<std::uint32_t> specialize_spirv(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features,
                                            SpirvCleanup cleanup) {
    std::unordered_map<std::uint32_t, std::string> values;
    for (std::size_t i = 0; i < kFeatureCount; ++i) {
        const std::uint32_t value = feature_value(features, i);
        values[kFeatures[i].id] = kFeatures[i].is_bool ? (value ? "true" : "false") : std::to_string(value);
    }
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2);
    optimizer.SetMessageConsumer([](spv_message_level_t, const char*, const spv_position_t&, const char*) {});
    optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(values))
        .RegisterPass(spvtools::CreateFreezeSpecConstantValuePass())
        .RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass());
    add_dead_code_rounds(optimizer, 2);
    if (cleanup == SpirvCleanup::local_variables && !optimizer.RegisterPassesFromFlags(kLocalVariablePasses))
        return spirv;
    // The module comes from glslang, and the driver (and the validation layer) check the result:
    // validating it here too would cost as much as the passes.
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);
    std::vector<std::uint32_t> out;
    if (!optimizer.Run(spirv.data(), spirv.size(), &out, options)) return spirv;
    // The longer recipe is checked: an optimizer bug must cost start-up time, not a driver crash.
    if (cleanup != SpirvCleanup::dead_code) {
        spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_2);
        if (!tools.Validate(out)) return specialize_spirv(spirv, features, SpirvCleanup::dead_code);
    }
    return out;
}

}  // namespace lancer::gpu

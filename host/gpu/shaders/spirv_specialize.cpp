#include "gpu/shaders/spirv_specialize.hpp"

#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include "gpu/shaders/spirv_passes.hpp"

namespace lancer::gpu {

namespace {

// The passes a cleanup runs after the dead-code rounds.
const std::vector<std::string>& passes_after_dead_code(SpirvCleanup cleanup) {
    static const std::vector<std::string> none;
    switch (cleanup) {
        case SpirvCleanup::dead_code: return none;
        case SpirvCleanup::local_variables: return kLocalVariablePasses;
        case SpirvCleanup::constants: return kConstantPasses;
    }
    return none;
}

}  // namespace

std::string spirv_recipe(SpirvCleanup cleanup) {
    std::string recipe = "specialise; 2 x (dead branches, dead code, dead functions, merge blocks)";
    for (const std::string& flag : passes_after_dead_code(cleanup)) recipe += " " + flag;
    return recipe;
}

SpirvCleanup spirv_cleanup_for(const ShaderFeatures& features, bool locals_in_ssa) {
    for (uint type = 0; type < SHAPE_COUNT; ++type)
        if (features.has_shape(type) && shape_has(type, SHAPE_KEEPS_LOCALS)) {
            if (locals_in_ssa)
                throw std::logic_error(std::string("spirv_cleanup_for: a module built with its locals as SSA values "
                                                   "has no code for ") + shape_name(type));
            return SpirvCleanup::dead_code;
        }
    return locals_in_ssa ? SpirvCleanup::constants : SpirvCleanup::local_variables;
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
    if (!optimizer.RegisterPassesFromFlags(passes_after_dead_code(cleanup))) return spirv;
    // The module comes from glslang (or the build's validated pruning), and the driver (and the validation layer) check the result:
    // validating it here too would cost as much as the passes.
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);
    std::vector<std::uint32_t> out;
    if (!optimizer.Run(spirv.data(), spirv.size(), &out, options)) return spirv;
    // The longer recipes are checked: an optimizer bug must cost start-up time, not a driver crash.
    if (cleanup != SpirvCleanup::dead_code) {
        spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_2);
        if (!tools.Validate(out)) return specialize_spirv(spirv, features, SpirvCleanup::dead_code);
    }
    return out;
}

}  // namespace lancer::gpu

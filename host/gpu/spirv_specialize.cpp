#include "gpu/spirv_specialize.hpp"

#include <string>
#include <unordered_map>

#include <spirv-tools/optimizer.hpp>

namespace lancer::gpu {

std::vector<std::uint32_t> specialize_spirv(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features) {
    std::unordered_map<std::uint32_t, std::string> values;
    for (const FeatureSpec& f : kFeatures) values[f.id] = features.*f.member ? "true" : "false";
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2);
    optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(values))
        .RegisterPass(spvtools::CreateFreezeSpecConstantValuePass())
        .RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass());
    // Two rounds: merging the blocks a first round left behind exposes more dead branches.
    for (int round = 0; round < 2; ++round)
        optimizer.RegisterPass(spvtools::CreateDeadBranchElimPass())
            .RegisterPass(spvtools::CreateAggressiveDCEPass())
            .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
            .RegisterPass(spvtools::CreateBlockMergePass());
    // The module comes from glslang, and the driver (and the validation layer) check the result:
    // validating it here too would cost as much as the passes.
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);
    std::vector<std::uint32_t> out;
    if (!optimizer.Run(spirv.data(), spirv.size(), &out, options)) return spirv;
    return out;
}

}  // namespace lancer::gpu

#pragma once
// The dead-code removal that lancer's specialisation (spirv_specialize) and the build-time pruning
// of the smaller tracers (spirv_prune) both run.
#include <spirv-tools/optimizer.hpp>

namespace lancer::gpu {

// `rounds` times dead branches, code and functions removed and blocks merged: merging the blocks
// a round left behind exposes more dead branches.
inline void add_dead_code_rounds(spvtools::Optimizer& optimizer, int rounds) {
    for (int round = 0; round < rounds; ++round)
        optimizer.RegisterPass(spvtools::CreateDeadBranchElimPass())
            .RegisterPass(spvtools::CreateAggressiveDCEPass())
            .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
            .RegisterPass(spvtools::CreateBlockMergePass());
}

}  // namespace lancer::gpu

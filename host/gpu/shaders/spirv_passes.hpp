#pragma once
// The SPIRV-Tools recipes that lancer's specialisation (spirv_specialize) and the build-time
// pruning of the smaller tracers (spirv_prune) share.
#include <string>
#include <vector>

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

// Local variables turned into SSA values, loads and stores folded: SPIRV-Tools' performance
// recipe (spirv-opt -O) without the passes measured to cost lavapipe's JIT code (inlining and
// merge-return: lavapipe inlines itself, and the merged returns become loops; scalar
// replacement; if-conversion) and without --simplify-instructions, whose folding of
// OpCompositeInserts gave a struct of the wrong (structurally equal) type in SPIRV-Tools 2022.4
// (an invalid module for the BVH tracer). `spirv-opt` with these flags reproduces it.
inline const std::vector<std::string> kLocalVariablePasses = {
    "--private-to-local", "--eliminate-local-single-block", "--eliminate-local-single-store",
    "--eliminate-dead-code-aggressive", "--convert-local-access-chains", "--eliminate-local-single-block",
    "--eliminate-local-single-store", "--eliminate-dead-code-aggressive", "--ssa-rewrite",
    "--eliminate-dead-code-aggressive", "--ccp", "--eliminate-dead-branches", "--redundancy-elimination",
    "--combine-access-chains", "--convert-local-access-chains", "--eliminate-local-single-block",
    "--eliminate-local-single-store", "--eliminate-dead-code-aggressive", "--ssa-rewrite",
    "--eliminate-dead-code-aggressive", "--vector-dce", "--eliminate-dead-inserts", "--eliminate-dead-branches",
    "--copy-propagate-arrays", "--reduce-load-size", "--eliminate-dead-code-aggressive", "--merge-blocks",
    "--redundancy-elimination", "--eliminate-dead-branches", "--merge-blocks"};

// After the dead code of a module whose local variables became SSA values at build time: what the
// frozen constants decide further: within 0.1% of the words the local-variable recipe gives, and
// the specialisation in about half the time (docs/performance.md).
inline const std::vector<std::string> kConstantPasses = {
    "--ccp", "--eliminate-dead-branches", "--redundancy-elimination", "--eliminate-dead-code-aggressive",
    "--merge-blocks"};

}  // namespace lancer::gpu

#pragma once
// The tracer's SPIR-V with its specialisation constants fixed and the code they switch off
// removed, before the driver sees it. lavapipe (Mesa 22.3) inlines every function into every
// call site before it folds specialisation constants, so the whole tracer, Bezier clipper and
// all, went through its NIR passes for every pipeline: 1.2 s of start-up for a sphere scene
// on a 2-core machine, against 0.2 s for the specialised module (docs/performance.md).
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/layout.hpp"

namespace lancer::gpu {

// What SPIRV-Tools does to the module beyond freezing the constants.
enum class SpirvCleanup : std::uint8_t {
    dead_code,        // dead branches, code and functions removed
    local_variables,  // also local variables turned into SSA values, loads and stores folded
    constants,        // dead code, then what the constants decide: for a module whose local
                      // variables became SSA values at build time (spirv_prune)
};

// The cleanup that pays on lavapipe for a tracer with these features. Turning local variables
// into SSA values before the driver sees the module takes a third off lavapipe's pipeline
// creation (a warm start of `seed` 0.12 -> 0.08 s, of the Barth sextic 0.48 -> 0.18 s), but
// slows some shapes' code (SHAPE_KEEPS_LOCALS in shapes.h): scenes with them keep the dead-code
// cleanup alone. A module built with its locals as SSA values (`locals_in_ssa`) has done that
// part already; it never holds those shapes' code (std::logic_error if the features have them).
SpirvCleanup spirv_cleanup_for(const ShaderFeatures& features, bool locals_in_ssa = false);

// The passes `cleanup` runs, in words and spirv-opt flags: what a cached module depends on.
std::string spirv_recipe(SpirvCleanup cleanup);

// `spirv` with each LANCER_FEATURES constant frozen at its value in `features` and `cleanup`
// done (SPIRV-Tools' optimizer). Returns `spirv` unchanged if the optimizer fails (the driver
// then specialises it itself).
std::vector<std::uint32_t> specialize_spirv(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features,
                                            SpirvCleanup cleanup = SpirvCleanup::dead_code);

}  // namespace lancer::gpu

#pragma once
// A tracer module built for fewer shape types (LANCER_BUILT_SHAPES, shaders/interface.glsl) with
// the code for the others removed, at build time. The shape flags of such a module test a
// specialisation constant against a zero mask (SCENE_SHAPES & 0u): true of every scene the module
// will serve, but SPIRV-Tools folds no expression of a specialisation constant, so this folds
// those first and then lets SPIRV-Tools remove what they leave dead. Every other specialisation
// constant stays one: the run-time specialisation of the result gives the same program as the
// whole module's (tests/unit/trace_modules_test.cpp).
#include <cstdint>
#include <vector>

namespace lancer::gpu {

// `spirv` with every specialisation-constant expression that is constant whatever the constants
// are (x & 0, x && false, x || true, and what those make foldable) folded, then dead branches,
// code and functions removed; with `locals_to_ssa`, then its local variables turned into SSA
// values (spirv_passes.hpp's kLocalVariablePasses), which the run-time specialisation then need
// not do (SpirvCleanup::constants). Throws std::runtime_error if the optimizer fails or the
// result does not validate (Vulkan 1.2).
std::vector<std::uint32_t> prune_spirv(const std::vector<std::uint32_t>& spirv, bool locals_to_ssa = false);

}  // namespace lancer::gpu

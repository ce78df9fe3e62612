#pragma once
// The tracer's SPIR-V with its specialisation constants fixed and the code they switch off
// removed, before the driver sees it. lavapipe (Mesa 22.3) inlines every function into every
// call site before it folds specialisation constants, so the whole tracer, Bezier clipper and
// all, went through its NIR passes for every pipeline: 1.2 s of start-up for a sphere scene
// on a 2-core machine, against 0.2 s for the specialised module (docs/performance.md).
#include <cstdint>
#include <vector>

#include "gpu/layout.hpp"

namespace lancer::gpu {

// `spirv` with each LANCER_FEATURES constant frozen at its value in `features`, dead branches,
// code and functions removed (SPIRV-Tools' optimizer). Returns `spirv` unchanged if the
// optimizer fails (the driver then specialises it itself).
std::vector<std::uint32_t> specialize_spirv(const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features);

}  // namespace lancer::gpu

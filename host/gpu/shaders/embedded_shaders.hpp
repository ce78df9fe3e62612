#pragma once
// The tracer as built into the binary, so `lancer` runs from any directory without shaders/:
// compiled to SPIR-V at build time (glslangValidator), and as source text for the run-time
// compiler. Both come from the same files and the same (empty) set of defines.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "gpu/layout.hpp"
#include "gpu/shaders/shader_compiler.hpp"

namespace lancer::gpu {

// The entry points compiled at build time: the tracer, photon mapping's photon pass and grid
// build, and adaptive anti-aliasing's selection of the pixels to refine.
inline constexpr const char* kTraceShader = "trace.comp";
inline constexpr const char* kPhotonShader = "photons.comp";
inline constexpr const char* kGridShader = "photon_grid.comp";
inline constexpr const char* kSelectShader = "refine_select.comp";

std::vector<std::uint32_t> embedded_trace_spirv();
// The SPIR-V of one of the entry points above.
std::vector<std::uint32_t> embedded_spirv(const std::string& entry);
// Whether a module built for `shape_types` alone (shapes.h's sets) serves a scene of `features`:
// every shape set of the features within them.
bool traces_only(const ShaderFeatures& features, std::uint32_t shape_types);
// An embedded build of an entry point, and whether its local variables became SSA values at
// build time (its specialisation then takes SpirvCleanup::constants: spirv_cleanup_for).
struct EmbeddedModule {
    std::vector<std::uint32_t> spirv;
    bool locals_in_ssa = false;
};
// The smallest embedded build of `entry` (the tracer, the photon pass) that serves `features`:
// the same program, once specialised, as the whole one, from 35-52% of the words for scenes of
// cheap or common shapes alone.
EmbeddedModule embedded_module(const std::string& entry, const ShaderFeatures& features);

// Every file of shaders/ by its name relative to that directory.
const std::map<std::string, std::string>& embedded_shader_files();
ShaderTree embedded_tree();

}  // namespace lancer::gpu

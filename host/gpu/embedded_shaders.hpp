#pragma once
// The tracer as built into the binary, so `lancer` runs from any directory without shaders/:
// compiled to SPIR-V at build time (glslangValidator), and as source text for the run-time
// compiler. Both come from the same files and the same (empty) set of defines.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "gpu/shader_compiler.hpp"

namespace lancer::gpu {

// The entry point compiled at build time.
inline constexpr const char* kTraceShader = "trace.comp";

std::vector<std::uint32_t> embedded_trace_spirv();

// Every file of shaders/ by its name relative to that directory.
const std::map<std::string, std::string>& embedded_shader_files();
ShaderTree embedded_tree();

}  // namespace lancer::gpu

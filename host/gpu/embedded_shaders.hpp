#pragma once
// The tracer compiled to SPIR-V at build time (glslangValidator) and linked into the binary, so
// `lancer render` runs from any directory without the shaders/ folder.
#include <cstdint>
#include <vector>

namespace lancer::gpu {

std::vector<std::uint32_t> embedded_trace_spirv();

}  // namespace lancer::gpu

#pragma once
// Runs a small compute shader of a test's own on the Vulkan device (validation on): GLSL
// functions of the tracer checked against the CPU's double-precision maths, value by value.
#include <cstdint>
#include <string>
#include <vector>

namespace lancer::test {

// `body` is GLSL placed after "#include "layout.h"", the workgroup size (1) and
// "buffer OutputBlock { vec4 data[]; }" at BINDING_OUTPUT; it may #include the tracer's shader
// files and must define main(). `data` is the buffer's contents before the dispatch of
// `invocations` workgroups; returns them after.
std::vector<float> run_kernel(const std::string& body, std::vector<float> data, std::uint32_t invocations);

}  // namespace lancer::test

#pragma once
// Runs a small GLSL compute shader on the Vulkan device, under the validation layer: for tests
// that check what generated shader code computes, away from the tracer.
#include <cstdint>
#include <string>
#include <vector>

namespace lancer::test {

// `glsl` is the shader after a fixed header (version 450, #include support, layout.h, local size
// 1 and `buffer OutputBlock { vec4 data[]; }` at BINDING_OUTPUT); it may #include the files of
// shaders/. `data` is the buffer's initial contents (a multiple of 4 floats); the shader runs
// `invocations` times and the buffer's final contents are returned.
std::vector<float> run_compute(const std::string& glsl, std::vector<float> data, std::uint32_t invocations);

}  // namespace lancer::test

#pragma once
// What the Vulkan driver takes in memory to start (instance, device, the tracer's pipeline and
// the LLVM compile behind it), estimated before any of it is created, so that a process under an
// address-space or cgroup limit too small for it gets a clear error (exit code 2) instead of a
// crash inside the driver, which does not check every allocation (docs/robustness.md, "Memory
// limits"). The figures are measured on lavapipe, the default device, the only one lancer's
// machines have; a real GPU's driver reserves address space of its own sort.
#include <cstdint>

#include "scene/scene.hpp"

namespace lancer::gpu {

// Throws UserError when starting the GPU backend does not fit under the process's limits.
void check_driver_startup_memory();

// What rendering `scene` takes beyond the driver's start: address space and resident memory.
struct RenderMemoryEstimate {
    std::uint64_t address_space;
    std::uint64_t resident;
};
RenderMemoryEstimate render_memory_estimate(const Scene& scene, std::uint64_t scene_buffer_bytes);
// The same from its parts: the pipeline's compile (compile_memory) is the objects', which a
// renderer reads before it packs them (and may free them: Renderer::render_once).
std::uint64_t compile_memory(const Scene& scene);
RenderMemoryEstimate render_memory_estimate(const RenderSettings& render, std::uint64_t scene_buffer_bytes,
                                            std::uint64_t compile_bytes);

// Throws UserError when a render of `render`'s size with the scene's buffers and a pipeline
// compile of `compile_bytes` (compile_memory) does not fit in what is left.
void check_render_memory(const RenderSettings& render, std::uint64_t scene_buffer_bytes, std::uint64_t compile_bytes);

}  // namespace lancer::gpu

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

// Throws UserError when rendering `scene` (its buffers, the image and the pipeline it needs) does
// not fit in what is left.
void check_render_memory(const Scene& scene, std::uint64_t scene_buffer_bytes);

}  // namespace lancer::gpu

#pragma once
// One recorded command buffer submitted and waited for, the wait cut into one-second slices so
// that a cancel request (Ctrl-C, a progress callback returning false) is noticed promptly.
#include <vulkan/vulkan.h>

#include "gpu/context.hpp"
#include "render/renderer.hpp"

namespace lancer::gpu {

// Resets `fence`, submits `commands` to the context's queue and waits for them. Between slices
// it reports `done` to `progress`; once that returns false it still waits for the GPU to finish
// (the buffers stay in use until then), then throws RenderCancelled.
void submit_and_wait(const Context& context, VkCommandBuffer commands, VkFence fence, const ProgressFn& progress,
                     double done);

}  // namespace lancer::gpu

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

// Records a barrier after compute shader writes: later compute shaders (by default) read and
// write what they wrote, or, with `dst` and `dst_stage`, the host reads it after the fence.
void compute_barrier(VkCommandBuffer commands, VkAccessFlags dst = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                     VkPipelineStageFlags dst_stage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);

}  // namespace lancer::gpu

#pragma once
// One recorded command buffer submitted and waited for, the wait cut into one-second slices so
// that a cancel request (Ctrl-C, a progress callback returning false) is noticed promptly.
#include <string>

#include <vulkan/vulkan.h>

#include "gpu/vulkan/context.hpp"
#include "render/renderer.hpp"

namespace lancer::gpu {

// Resets `fence`, submits `commands` to the context's queue and waits for them. Between slices
// it reports `done` to `progress`; once that returns false it still waits for the GPU to finish
// (the buffers stay in use until then), then throws RenderCancelled.
void submit_and_wait(const Context& context, VkCommandBuffer commands, VkFence fence, const ProgressFn& progress,
                     double done);

// A primary command buffer and the fence its submissions signal, named after what they do
// (validation messages say "<name>" and "<name> done"), recorded again for every submission.
// Its owner waits for the device to be idle before destroying it.
class Submission {
public:
    Submission(const Context& context, const std::string& name);
    ~Submission();
    Submission(const Submission&) = delete;
    Submission& operator=(const Submission&) = delete;

    // Resets the command buffer and begins recording it for one submission.
    VkCommandBuffer begin() const;
    VkCommandBuffer commands() const { return commands_; }
    // Ends the recording, submits it and waits (submit_and_wait).
    void end_and_wait(const ProgressFn& progress, double done) const;

private:
    const Context& context_;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

// Records a barrier after compute shader writes: later compute shaders (by default) read and
// write what they wrote, or, with `dst` and `dst_stage`, the host reads it after the fence.
void compute_barrier(VkCommandBuffer commands, VkAccessFlags dst = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                     VkPipelineStageFlags dst_stage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);

}  // namespace lancer::gpu

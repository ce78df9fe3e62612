#include "gpu/submit.hpp"

#include "gpu/vk_check.hpp"

namespace lancer::gpu {

void submit_and_wait(const Context& context, VkCommandBuffer commands, VkFence fence, const ProgressFn& progress,
                     double done) {
    VkDevice device = context.device();
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    VK_CHECK(vkResetFences(device, 1, &fence));
    VK_CHECK(vkQueueSubmit(context.queue(), 1, &submit, fence));
    bool cancel = false;
    for (;;) {
        VkResult r = vkWaitForFences(device, 1, &fence, VK_TRUE, 1'000'000'000ull);
        if (r == VK_SUCCESS) break;
        if (r != VK_TIMEOUT) VK_CHECK(r);
        if (progress && !cancel && !progress(done)) cancel = true;
    }
    if (cancel) throw RenderCancelled();
}

void compute_barrier(VkCommandBuffer commands, VkAccessFlags dst, VkPipelineStageFlags dst_stage) {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    b.dstAccessMask = dst;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, dst_stage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

}  // namespace lancer::gpu

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

}  // namespace lancer::gpu

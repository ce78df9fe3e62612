#include "gpu/vulkan/submit.hpp"

#include "gpu/vulkan/vk_check.hpp"

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

Submission::Submission(const Context& context, const std::string& name) : context_(context) {
    VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    info.commandPool = context.command_pool();
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(context.device(), &info, &commands_));
    context.set_name(VK_OBJECT_TYPE_COMMAND_BUFFER, commands_, name);
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    try {
        VK_CHECK(vkCreateFence(context.device(), &fence_info, nullptr, &fence_));
    } catch (...) {
        vkFreeCommandBuffers(context.device(), context.command_pool(), 1, &commands_);
        throw;
    }
    context.set_name(VK_OBJECT_TYPE_FENCE, fence_, name + " done");
}

Submission::~Submission() {
    vkDestroyFence(context_.device(), fence_, nullptr);
    vkFreeCommandBuffers(context_.device(), context_.command_pool(), 1, &commands_);
}

VkCommandBuffer Submission::begin() const {
    VK_CHECK(vkResetCommandBuffer(commands_, 0));
    VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands_, &info));
    return commands_;
}

void Submission::end_and_wait(const ProgressFn& progress, double done) const {
    VK_CHECK(vkEndCommandBuffer(commands_));
    submit_and_wait(context_, commands_, fence_, progress, done);
}

void compute_barrier(VkCommandBuffer commands, VkAccessFlags dst, VkPipelineStageFlags dst_stage) {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    b.dstAccessMask = dst;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, dst_stage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

}  // namespace lancer::gpu

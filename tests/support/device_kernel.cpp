#include "support/device_kernel.hpp"

#include <cstring>
#include <optional>

#include "gpu/buffer.hpp"
#include "gpu/context.hpp"
#include "gpu/layout.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/shader_compiler.hpp"
#include "gpu/vk_check.hpp"
#include "support/test_support.hpp"

namespace lancer::test {

std::vector<float> run_kernel(const std::string& body, std::vector<float> data, std::uint32_t invocations) {
    const std::string source = "#version 450\n#extension GL_GOOGLE_include_directive : require\n"
                               "#extension GL_EXT_control_flow_attributes : require\n#include \"layout.h\"\n"
                               "layout(local_size_x = 1) in;\n"
                               "layout(std430, set = 0, binding = BINDING_OUTPUT) buffer OutputBlock { vec4 data[]; };\n" +
                               body;
    auto shaders = gpu::directory_tree(source_path("shaders"));
    auto tree = [&](const std::string& name) -> std::optional<std::string> {
        if (name == "trace.comp") return source;
        return shaders(name);
    };
    std::vector<std::uint32_t> spirv = gpu::compile_compute(tree, "trace.comp");

    gpu::Context context(gpu::ContextOptions{"", /*validation=*/true});
    gpu::TraceLayout layout(context);
    gpu::ComputePipeline pipeline(context, layout, spirv, gpu::PipelineVariant{});
    const std::size_t bytes = data.size() * sizeof(float);
    gpu::Buffer buffer(context, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    buffer.write(data.data(), bytes);

    VkDevice device = context.device();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = 1;
    pool_info.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(device, &pool_info, nullptr, &pool));
    VkDescriptorSetLayout set_layout = layout.set_layout();
    VkDescriptorSetAllocateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    set_info.descriptorPool = pool;
    set_info.descriptorSetCount = 1;
    set_info.pSetLayouts = &set_layout;
    VkDescriptorSet set = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateDescriptorSets(device, &set_info, &set));
    VkDescriptorBufferInfo info{buffer.handle(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set;
    write.dstBinding = gpu::BINDING_OUTPUT;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);

    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = context.command_pool();
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(device, &alloc, &commands));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands, &begin));
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout.pipeline_layout(), 0, 1, &set, 0,
                            nullptr);
    vkCmdDispatch(commands, invocations, 1, 1);
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                         nullptr, 0, nullptr);
    VK_CHECK(vkEndCommandBuffer(commands));
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(device, &fence_info, nullptr, &fence));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    VK_CHECK(vkQueueSubmit(context.queue(), 1, &submit, fence));
    VK_CHECK(vkWaitForFences(device, 1, &fence, VK_TRUE, 60'000'000'000ull));
    std::memcpy(data.data(), buffer.data(), bytes);
    vkDestroyFence(device, fence, nullptr);
    vkFreeCommandBuffers(device, context.command_pool(), 1, &commands);
    vkDestroyDescriptorPool(device, pool, nullptr);
    return data;
}

}  // namespace lancer::test

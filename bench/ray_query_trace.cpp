#include "ray_query_trace.hpp"

#include <array>
#include <cstring>

#include "gpu/vulkan/vk_check.hpp"
#include "ray_query.spv.h"

namespace lancer::bench {
namespace {

constexpr std::uint32_t kGroupSide = 8;  // ray_query.comp's local size, 8 x 8

// The shader's bindings, in order: 0 the structure, 1-4 storage buffers, 5 the view.
constexpr std::array<VkDescriptorType, 6> kBindings = {
    VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
    VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};

constexpr VkBufferUsageFlags kMeshUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                                          VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;

template <class T>
DeviceBuffer filled(const RayQueryDevice& device, const std::vector<T>& values, VkBufferUsageFlags usage) {
    DeviceBuffer buffer = device.buffer(values.size() * sizeof(T), usage, "input");
    std::memcpy(buffer.data(), values.data(), values.size() * sizeof(T));
    return buffer;
}

}  // namespace

RayQueryTracer::RayQueryTracer(const RayQueryDevice& device, const MeshSet& set, const ViewBlock& view)
    : device_(device), view_(view) {
    VkDevice vk = device.device();
    positions_ = filled(device, set.positions, kMeshUsage);
    indices_ = filled(device, set.indices, kMeshUsage);
    std::vector<glm::uvec2> starts;
    for (const MeshRange& m : set.meshes) starts.emplace_back(m.first_index, m.first_vertex);
    mesh_starts_ = filled(device, starts, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    pixels_ = device.buffer(VkDeviceSize(view.size.x) * view.size.y * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "pixels");
    view_buffer_ = filled(device, std::vector<ViewBlock>{view}, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);

    std::array<VkDescriptorSetLayoutBinding, kBindings.size()> bindings{};
    std::array<VkDescriptorPoolSize, kBindings.size()> pool_sizes{};
    for (std::uint32_t i = 0; i < kBindings.size(); ++i) {
        bindings[i] = {i, kBindings[i], 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
        pool_sizes[i] = {kBindings[i], 1};
    }
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = static_cast<std::uint32_t>(bindings.size());
    set_info.pBindings = bindings.data();
    VK_CHECK(vkCreateDescriptorSetLayout(vk, &set_info, nullptr, &set_layout_));
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout_;
    VK_CHECK(vkCreatePipelineLayout(vk, &layout_info, nullptr, &pipeline_layout_));

    VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    module_info.codeSize = sizeof lancer_ray_query_spv;
    module_info.pCode = lancer_ray_query_spv;
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(vk, &module_info, nullptr, &module));
    VkComputePipelineCreateInfo pipeline_info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipeline_info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pipeline_info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipeline_info.stage.module = module;
    pipeline_info.stage.pName = "main";
    pipeline_info.layout = pipeline_layout_;
    VkResult made = vkCreateComputePipelines(vk, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &pipeline_);
    vkDestroyShaderModule(vk, module, nullptr);
    VK_CHECK(made);

    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = static_cast<std::uint32_t>(pool_sizes.size());
    pool_info.pPoolSizes = pool_sizes.data();
    VK_CHECK(vkCreateDescriptorPool(vk, &pool_info, nullptr, &pool_));
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = pool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout_;
    VK_CHECK(vkAllocateDescriptorSets(vk, &alloc, &set_));

    const DeviceBuffer* buffers[] = {&positions_, &indices_, &mesh_starts_, &pixels_, &view_buffer_};
    std::array<VkDescriptorBufferInfo, 5> infos{};
    std::array<VkWriteDescriptorSet, 5> writes{};
    for (std::uint32_t i = 0; i < infos.size(); ++i) {
        infos[i] = {buffers[i]->handle(), 0, VK_WHOLE_SIZE};
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set_;
        writes[i].dstBinding = i + 1;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = kBindings[i + 1];
        writes[i].pBufferInfo = &infos[i];
    }
    vkUpdateDescriptorSets(vk, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

RayQueryTracer::~RayQueryTracer() {
    VkDevice vk = device_.device();
    vkDeviceWaitIdle(vk);
    if (pool_) vkDestroyDescriptorPool(vk, pool_, nullptr);
    if (pipeline_) vkDestroyPipeline(vk, pipeline_, nullptr);
    if (pipeline_layout_) vkDestroyPipelineLayout(vk, pipeline_layout_, nullptr);
    if (set_layout_) vkDestroyDescriptorSetLayout(vk, set_layout_, nullptr);
}

double RayQueryTracer::trace(VkAccelerationStructureKHR top) {
    // Each build makes a new structure: the set points at this one.
    VkWriteDescriptorSetAccelerationStructureKHR structure{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
    structure.accelerationStructureCount = 1;
    structure.pAccelerationStructures = &top;
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.pNext = &structure;
    write.dstSet = set_;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
    vkUpdateDescriptorSets(device_.device(), 1, &write, 0, nullptr);

    return device_.run([&](VkCommandBuffer commands) {
        VkMemoryBarrier built{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        built.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
        built.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
        vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                             VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &built, 0, nullptr, 0, nullptr);
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
        vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set_, 0, nullptr);
        vkCmdDispatch(commands, (view_.size.x + kGroupSide - 1) / kGroupSide, (view_.size.y + kGroupSide - 1) / kGroupSide, 1);
        VkMemoryBarrier written{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        written.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        written.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &written, 0,
                             nullptr, 0, nullptr);
    });
}

FloatImage RayQueryTracer::picture() const {
    FloatImage image(static_cast<int>(view_.size.x), static_cast<int>(view_.size.y));
    std::memcpy(image.pixels.data(), pixels_.data(), image.pixels.size() * sizeof(glm::vec4));
    return image;
}

}  // namespace lancer::bench

#include "gpu/pipeline.hpp"

#include <array>
#include <iterator>
#include <string>
#include <utility>

#include "gpu/layout.hpp"
#include "gpu/resource_kinds.hpp"
#include "gpu/vk_check.hpp"

namespace lancer::gpu {

TraceLayout::TraceLayout(const Context& context) : device_(context.device()) {
    std::array<VkDescriptorSetLayoutBinding, kResourceCount> bindings{};
    for (std::size_t i = 0; i < kResourceCount; ++i) {
        bindings[i].binding = kResources[i].binding;
        bindings[i].descriptorType = descriptor_type(kResources[i].kind);
        bindings[i].descriptorCount = 1;
        bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    try {
        VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        set_info.bindingCount = static_cast<std::uint32_t>(bindings.size());
        set_info.pBindings = bindings.data();
        VK_CHECK(vkCreateDescriptorSetLayout(device_, &set_info, nullptr, &set_layout_));
        context.set_name(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, set_layout_, "tracer descriptors");

        VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(BandParams)};
        VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layout_info.setLayoutCount = 1;
        layout_info.pSetLayouts = &set_layout_;
        layout_info.pushConstantRangeCount = 1;
        layout_info.pPushConstantRanges = &push;
        VK_CHECK(vkCreatePipelineLayout(device_, &layout_info, nullptr, &pipeline_layout_));
        context.set_name(VK_OBJECT_TYPE_PIPELINE_LAYOUT, pipeline_layout_, "tracer");
    } catch (...) {
        release();
        throw;
    }
}

TraceLayout::~TraceLayout() { release(); }

void TraceLayout::release() noexcept {
    if (pipeline_layout_) vkDestroyPipelineLayout(device_, pipeline_layout_, nullptr);
    if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
    pipeline_layout_ = VK_NULL_HANDLE;
    set_layout_ = VK_NULL_HANDLE;
}

ComputePipeline::ComputePipeline(const Context& context, const TraceLayout& layout,
                                 const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features)
    : device_(context.device()) {
    constexpr std::size_t kCount = std::size(kFeatures);
    std::array<VkBool32, kCount> values{};
    std::array<VkSpecializationMapEntry, kCount> entries{};
    std::string name = "tracer";
    for (std::size_t i = 0; i < kCount; ++i) {
        const bool on = features.*kFeatures[i].member;
        values[i] = on ? VK_TRUE : VK_FALSE;
        entries[i] = {kFeatures[i].id, static_cast<std::uint32_t>(i * sizeof(VkBool32)), sizeof(VkBool32)};
        if (on) name += std::string(" ") + kFeatures[i].name;
    }
    VkSpecializationInfo specialization{};
    specialization.mapEntryCount = static_cast<std::uint32_t>(kCount);
    specialization.pMapEntries = entries.data();
    specialization.dataSize = sizeof(values);
    specialization.pData = values.data();

    VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    module_info.codeSize = spirv.size() * sizeof(std::uint32_t);
    module_info.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(device_, &module_info, nullptr, &module));

    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = &specialization;
    info.layout = layout.pipeline_layout();
    VkResult result = vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_);
    vkDestroyShaderModule(device_, module, nullptr);
    VK_CHECK(result);
    context.set_name(VK_OBJECT_TYPE_PIPELINE, pipeline_, name);
}

ComputePipeline::~ComputePipeline() {
    if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
}

}  // namespace lancer::gpu

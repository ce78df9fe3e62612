#pragma once
// The tracer's pipeline layout (the descriptors of LANCER_RESOURCES in shaders/layout.h, created
// once per device) and the compute pipeline built against it from SPIR-V and the specialisation
// constants of LANCER_FEATURES, which can be replaced (hot reload, expression surfaces) without
// touching descriptor sets.
#include <cstdint>
#include <vector>

#include "gpu/context.hpp"
#include "gpu/layout.hpp"

namespace lancer::gpu {

class TraceLayout {
public:
    explicit TraceLayout(const Context& context);
    ~TraceLayout();
    TraceLayout(const TraceLayout&) = delete;
    TraceLayout& operator=(const TraceLayout&) = delete;

    VkDescriptorSetLayout set_layout() const { return set_layout_; }
    VkPipelineLayout pipeline_layout() const { return pipeline_layout_; }

private:
    void release() noexcept;

    VkDevice device_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
};

class ComputePipeline {
public:
    ComputePipeline(const Context& context, const TraceLayout& layout, const std::vector<std::uint32_t>& spirv,
                    const ShaderFeatures& features);
    ~ComputePipeline();
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;

    VkPipeline handle() const { return pipeline_; }

private:
    VkDevice device_;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace lancer::gpu

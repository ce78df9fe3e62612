#pragma once
// The tracer's compute pipeline and the descriptor set layout it is built against (bindings
// from shaders/layout.h). Rebuilding it from new SPIR-V (hot reload) leaves the layout alone.
#include <cstdint>
#include <vector>

#include "gpu/context.hpp"

namespace lancer::gpu {

class TracePipeline {
public:
    TracePipeline(const Context& context, const std::vector<std::uint32_t>& spirv);
    ~TracePipeline();
    TracePipeline(const TracePipeline&) = delete;
    TracePipeline& operator=(const TracePipeline&) = delete;

    VkPipeline pipeline() const { return pipeline_; }
    VkPipelineLayout layout() const { return layout_; }
    VkDescriptorSetLayout set_layout() const { return set_layout_; }

private:
    void release() noexcept;

    VkDevice device_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace lancer::gpu

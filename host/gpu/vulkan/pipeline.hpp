#pragma once
// The tracer's pipeline layout (the descriptors of LANCER_RESOURCES in shaders/layout.h, created
// once per device) and the compute pipeline built against it from SPIR-V and the specialisation
// constants of LANCER_FEATURES, which can be replaced (hot reload, expression surfaces) without
// touching descriptor sets.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gpu/vulkan/context.hpp"
#include "gpu/layout.hpp"
#include "gpu/shaders/spirv_specialize.hpp"

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
    // `name` labels it for validation messages and debuggers, followed by the features it has on.
    ComputePipeline(const Context& context, const TraceLayout& layout, const std::vector<std::uint32_t>& spirv,
                    const ShaderFeatures& features, const std::string& name = "tracer",
                    SpirvCleanup cleanup = SpirvCleanup::dead_code);
    ~ComputePipeline();
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;

    VkPipeline handle() const { return pipeline_; }

private:
    VkDevice device_;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

// A ComputePipeline being built by the driver on a thread of its own. lavapipe compiles a big
// tracer (many expression surfaces) for minutes, inside one vkCreateComputePipelines call that
// nothing can interrupt; the thread that waits for it can stop waiting instead, and leave the
// build to finish (and be destroyed) in the background. The build holds the context and the
// layout it uses, so they outlive it whatever the renderer does meanwhile.
class PipelineBuild {
public:
    PipelineBuild(std::shared_ptr<const Context> context, std::shared_ptr<const TraceLayout> layout,
                  std::vector<std::uint32_t> spirv, const ShaderFeatures& features, SpirvCleanup cleanup);
    ~PipelineBuild();  // abandons a build still running
    PipelineBuild(const PipelineBuild&) = delete;
    PipelineBuild& operator=(const PipelineBuild&) = delete;

    // The pipeline once built, asking `keep_waiting` about every 100 ms meanwhile: nullptr
    // when it says stop (the build goes on; a later wait() picks it up). Rethrows the build's
    // error (VulkanError).
    ComputePipeline* wait(const std::function<bool()>& keep_waiting);

private:
    struct State;
    std::shared_ptr<State> state_;
};

// Pipeline builds abandoned and still running in this process. main() must not run the exit
// handlers (the driver's and LLVM's static destructors) under them: it leaves with _Exit().
int abandoned_pipeline_builds();
// Waits until none is running: for a process that must end normally (the tests' main), which a
// build still inside the driver would bring down as its libraries are unloaded.
void wait_for_abandoned_pipeline_builds();

}  // namespace lancer::gpu

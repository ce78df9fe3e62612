#include "support/gpu_kernel.hpp"

#include <cstring>
#include <optional>

#include "gpu/vulkan/pipeline.hpp"
#include "gpu/shaders/shader_compiler.hpp"
#include "gpu/trace_resources.hpp"
#include "gpu/vulkan/vk_check.hpp"
#include "support/test_support.hpp"

namespace lancer::test {

struct GpuKernel::State {
    const gpu::Context& context;
    gpu::TraceLayout layout;
    gpu::ComputePipeline pipeline;
    gpu::TraceResources resources;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;

    State(const gpu::Context& c, const std::vector<std::uint32_t>& spirv, const gpu::ShaderFeatures& features)
        : context(c), layout(c), pipeline(c, layout, spirv, features), resources(c, layout.set_layout()) {
        VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        alloc.commandPool = c.command_pool();
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        VK_CHECK(vkAllocateCommandBuffers(c.device(), &alloc, &commands));
        VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(c.device(), &fence_info, nullptr, &fence));
    }
    ~State() {
        vkDestroyFence(context.device(), fence, nullptr);
        vkFreeCommandBuffers(context.device(), context.command_pool(), 1, &commands);
    }
};

gpu::ShaderFeatures GpuKernel::all_features() {
    gpu::ShaderFeatures f;
#define LANCER_FEATURE_ON(NAME, id, type, member, fallback) f.member = static_cast<type>(~0u);
    LANCER_FEATURES(LANCER_FEATURE_ON)
#undef LANCER_FEATURE_ON
    f.output_hits = false;
    f.check_loop_limit = false;
    f.check_grid_contract = false;
    f.spheres_by_near_points = false;  // as the packer packs spheres unless a scene needs it
    return f;
}

GpuKernel::GpuKernel(const std::string& source, const std::string& surface_code, const gpu::ShaderFeatures& features) {
    auto shaders = gpu::directory_tree(source_path("shaders"));
    auto tree = [&](const std::string& name) -> std::optional<std::string> {
        if (name == "kernel.comp") return source;
        if (name == "surface_functions.glsl" && !surface_code.empty()) return surface_code;
        return shaders(name);
    };
    state_ = std::make_unique<State>(gpu_renderer().context(), gpu::compile_compute(tree, "kernel.comp"), features);
}

GpuKernel::~GpuKernel() = default;

std::vector<glm::vec4> GpuKernel::run(const gpu::PackedScene& scene, const gpu::FrameParams& frame,
                                      const std::vector<glm::vec4>& io, std::uint32_t invocations) {
    State& s = *state_;
    VkDevice device = s.context.device();
    s.resources.upload(scene, frame);
    const std::size_t bytes = io.size() * sizeof(glm::vec4);
    const gpu::Buffer& output = s.resources.output(bytes);
    if (bytes) std::memcpy(output.data(), io.data(), bytes);

    VK_CHECK(vkResetCommandBuffer(s.commands, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(s.commands, &begin));
    vkCmdBindPipeline(s.commands, VK_PIPELINE_BIND_POINT_COMPUTE, s.pipeline.handle());
    VkDescriptorSet set = s.resources.descriptor_set();
    vkCmdBindDescriptorSets(s.commands, VK_PIPELINE_BIND_POINT_COMPUTE, s.layout.pipeline_layout(), 0, 1, &set, 0,
                            nullptr);
    gpu::BandParams band{};
    vkCmdPushConstants(s.commands, s.layout.pipeline_layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(band), &band);
    vkCmdDispatch(s.commands, invocations, 1, 1);
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(s.commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier,
                         0, nullptr, 0, nullptr);
    VK_CHECK(vkEndCommandBuffer(s.commands));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &s.commands;
    VK_CHECK(vkResetFences(device, 1, &s.fence));
    VK_CHECK(vkQueueSubmit(s.context.queue(), 1, &submit, s.fence));
    VK_CHECK(vkWaitForFences(device, 1, &s.fence, VK_TRUE, 600'000'000'000ull));
    std::vector<glm::vec4> result(io.size());
    if (bytes) std::memcpy(result.data(), output.data(), bytes);
    return result;
}

}  // namespace lancer::test

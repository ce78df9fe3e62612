#include "gpu/vulkan/pipeline.hpp"

#include <array>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <iterator>
#include <mutex>
#include <string>
#include <thread>
#include <utility>

#include <fmt/format.h>

#include "core/sha256.hpp"
#include "gpu/layout.hpp"
#include "gpu/vulkan/resource_kinds.hpp"
#include "gpu/shaders/spirv_cache.hpp"
#include "gpu/vulkan/vk_check.hpp"

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
                                 const std::vector<std::uint32_t>& spirv, const ShaderFeatures& features,
                                 const std::string& pipeline_name, SpirvCleanup cleanup)
    : device_(context.device()) {
    std::array<std::uint32_t, kFeatureCount> values{};  // a VkBool32 or a uint each
    std::array<VkSpecializationMapEntry, kFeatureCount> entries{};
    std::string name = pipeline_name;
    for (std::size_t i = 0; i < kFeatureCount; ++i) {
        values[i] = feature_value(features, i);
        entries[i] = {kFeatures[i].id, static_cast<std::uint32_t>(i * sizeof(std::uint32_t)), sizeof(std::uint32_t)};
        if (kFeatures[i].is_bool && values[i]) name += std::string(" ") + kFeatures[i].name;
        if (!kFeatures[i].is_bool) name += fmt::format(" {}={:#x}", kFeatures[i].name, values[i]);
    }
    VkSpecializationInfo specialization{};
    specialization.mapEntryCount = static_cast<std::uint32_t>(kFeatureCount);
    specialization.pMapEntries = entries.data();
    specialization.dataSize = sizeof(values);
    specialization.pData = values.data();

    const std::vector<std::uint32_t> specialized = cached_specialization(spirv, features, cleanup);
    VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    module_info.codeSize = specialized.size() * sizeof(std::uint32_t);
    module_info.pCode = specialized.data();
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

namespace {

// Abandoned builds still running, and a way to wait for the last of them.
std::mutex g_abandoned_mutex;
std::condition_variable g_abandoned_finished;
int g_abandoned = 0;

}  // namespace

struct PipelineBuild::State {
    std::shared_ptr<const Context> context;  // the device and layout stay alive while the build runs
    std::shared_ptr<const TraceLayout> layout;
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    bool abandoned = false;
    std::unique_ptr<ComputePipeline> pipeline;  // destroyed before the layout and the context
    std::exception_ptr error;
};

PipelineBuild::PipelineBuild(std::shared_ptr<const Context> context, std::shared_ptr<const TraceLayout> layout,
                             std::vector<std::uint32_t> spirv, const ShaderFeatures& features, SpirvCleanup cleanup)
    : state_(std::make_shared<State>()) {
    state_->context = std::move(context);
    state_->layout = std::move(layout);
    std::thread([state = state_, spirv = std::move(spirv), features, cleanup]() mutable {
        std::unique_ptr<ComputePipeline> pipeline;
        std::exception_ptr error;
        try {
            pipeline = std::make_unique<ComputePipeline>(*state->context, *state->layout, spirv, features, "tracer", cleanup);
        } catch (...) {
            error = std::current_exception();
        }
        bool abandoned = false;
        {
            std::lock_guard lock(state->mutex);
            state->pipeline = std::move(pipeline);
            state->error = error;
            state->done = true;
            abandoned = state->abandoned;
            state->finished.notify_all();
        }
        // An abandoned build is the last owner: this destroys the pipeline, and maybe the layout
        // and the device. Only then does it stop counting as running.
        state.reset();
        release_thread_hash_state();  // the SPIR-V cache's hashing ran on this thread
        if (abandoned) {
            std::lock_guard count_lock(g_abandoned_mutex);
            if (--g_abandoned == 0) g_abandoned_finished.notify_all();
        }
    }).detach();
}

PipelineBuild::~PipelineBuild() {
    {
        std::lock_guard lock(state_->mutex);
        if (!state_->done) {
            state_->abandoned = true;
            std::lock_guard count_lock(g_abandoned_mutex);
            ++g_abandoned;
            return;
        }
    }
    // Finished: the worker is about to drop its reference, if it has not yet. Wait for that, so
    // that the pipeline is destroyed here, by its owner, not by a thread nobody waits for.
    while (state_.use_count() > 1) std::this_thread::yield();
}

ComputePipeline* PipelineBuild::wait(const std::function<bool()>& keep_waiting) {
    std::unique_lock lock(state_->mutex);
    while (!state_->finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return state_->done; })) {
        lock.unlock();
        bool go_on = !keep_waiting || keep_waiting();
        lock.lock();
        if (!go_on && !state_->done) return nullptr;
    }
    if (state_->error) std::rethrow_exception(state_->error);
    return state_->pipeline.get();
}

int abandoned_pipeline_builds() {
    std::lock_guard lock(g_abandoned_mutex);
    return g_abandoned;
}

void wait_for_abandoned_pipeline_builds() {
    std::unique_lock lock(g_abandoned_mutex);
    g_abandoned_finished.wait(lock, [] { return g_abandoned == 0; });
}

}  // namespace lancer::gpu

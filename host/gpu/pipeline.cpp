#include "gpu/pipeline.hpp"

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <iterator>
#include <mutex>
#include <thread>
#include <utility>

#include "gpu/layout.hpp"
#include "gpu/vk_check.hpp"

namespace lancer::gpu {

TraceLayout::TraceLayout(const Context& context) : device_(context.device()) {
    const std::array<std::pair<uint, VkDescriptorType>, 13> kinds = {{
        {BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
        {BINDING_PRIMITIVES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {BINDING_NODES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {BINDING_PATCHES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {BINDING_SURFACES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {BINDING_CELLS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {BINDING_TEXTURES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {BINDING_TEXELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {BINDING_PATTERNS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {BINDING_PERMUTATION, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
    }};
    std::array<VkDescriptorSetLayoutBinding, kinds.size()> bindings{};
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        bindings[i].binding = kinds[i].first;
        bindings[i].descriptorType = kinds[i].second;
        bindings[i].descriptorCount = 1;
        bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    }
    try {
        VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        set_info.bindingCount = static_cast<std::uint32_t>(bindings.size());
        set_info.pBindings = bindings.data();
        VK_CHECK(vkCreateDescriptorSetLayout(device_, &set_info, nullptr, &set_layout_));

        VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(BandParams)};
        VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layout_info.setLayoutCount = 1;
        layout_info.pSetLayouts = &set_layout_;
        layout_info.pushConstantRangeCount = 1;
        layout_info.pPushConstantRanges = &push;
        VK_CHECK(vkCreatePipelineLayout(device_, &layout_info, nullptr, &pipeline_layout_));
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
                                 const std::vector<std::uint32_t>& spirv, const PipelineVariant& variant)
    : device_(context.device()) {
    const std::pair<uint, bool> constants[] = {
        {SPEC_HAS_BEZIER, variant.has_bezier},
        {SPEC_HAS_BVH, variant.has_bvh},
        {SPEC_OUTPUT_HITS, variant.output_hits},
        {SPEC_CHECK_LOOP_LIMIT, variant.check_loop_limit},
        {SPEC_HAS_TEXTURES, variant.has_textures},
        {SPEC_HAS_PATTERNS, variant.has_patterns},
        {SPEC_HAS_TRANSPARENCY, variant.has_transparency},
        {SPEC_HAS_AREA_LIGHTS, variant.has_area_lights},
        {SPEC_HAS_SPOT_LIGHTS, variant.has_spot_lights},
        {SPEC_HAS_FALLOFF, variant.has_falloff},
        {SPEC_HAS_BLINN, variant.has_blinn},
    };
    constexpr std::size_t kCount = std::size(constants);
    std::array<VkBool32, kCount> values{};
    std::array<VkSpecializationMapEntry, kCount> entries{};
    for (std::size_t i = 0; i < kCount; ++i) {
        values[i] = constants[i].second ? VK_TRUE : VK_FALSE;
        entries[i] = {constants[i].first, static_cast<std::uint32_t>(i * sizeof(VkBool32)), sizeof(VkBool32)};
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
}

ComputePipeline::~ComputePipeline() {
    if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
}

namespace {

std::atomic<int> g_abandoned{0};

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
                             std::vector<std::uint32_t> spirv, const PipelineVariant& variant)
    : state_(std::make_shared<State>()) {
    state_->context = std::move(context);
    state_->layout = std::move(layout);
    std::thread([state = state_, spirv = std::move(spirv), variant]() mutable {
        std::unique_ptr<ComputePipeline> pipeline;
        std::exception_ptr error;
        try {
            pipeline = std::make_unique<ComputePipeline>(*state->context, *state->layout, spirv, variant);
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
        if (abandoned) --g_abandoned;
    }).detach();
}

PipelineBuild::~PipelineBuild() {
    {
        std::lock_guard lock(state_->mutex);
        if (!state_->done) {
            state_->abandoned = true;
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

int abandoned_pipeline_builds() { return g_abandoned.load(); }

}  // namespace lancer::gpu

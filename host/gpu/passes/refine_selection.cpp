#include "gpu/passes/refine_selection.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "gpu/vulkan/submit.hpp"
#include "gpu/vulkan/vk_check.hpp"
#include "image/difference_tables.hpp"
#include "image/image.hpp"

namespace lancer::gpu {
namespace {

// The tracer's pipeline layout has push constants the size of BandParams (gpu/vulkan/pipeline.cpp).
static_assert(sizeof(SelectStep) <= sizeof(BandParams), "SelectStep must fit the push constant range");

// The workgroups (and blocks of the prefix sums) that cover `items` pixels or list entries.
std::uint64_t blocks_of(std::uint64_t items) { return (items + SELECT_BLOCK - 1) / SELECT_BLOCK; }

}  // namespace

RefineSelection::RefineSelection(const Context& context, const TraceLayout& layout, const std::vector<std::uint32_t>& spirv)
    : context_(context), layout_(layout), pipeline_(context, layout, spirv, ShaderFeatures{}, "refine selection"),
      submission_(context, "refine selection") {}

RefineSelection::~RefineSelection() { vkDeviceWaitIdle(context_.device()); }

std::vector<BufferNeed> RefineSelection::buffer_needs(std::uint64_t pixels) {
    return {resource_need(BINDING_PICTURE, pixels),
            resource_need(BINDING_PICTURE_CODES, pixels),
            resource_need(BINDING_REFINE_FLAGS, pixels),
            resource_need(BINDING_REFINE, pixels),
            resource_need(BINDING_BLOCK_SUMS, blocks_of(pixels) + 1),
            resource_need(BINDING_SRGB_LEVELS, 256),
            resource_need(BINDING_DIFFERENCE_FLOORS, 256 * 256)};
}

bool RefineSelection::fits(std::uint64_t pixels, const Context& context) {
    if (blocks_of(pixels) > context.limits().maxComputeWorkGroupCount[0]) return false;
    const DeviceMemoryLimits limits = buffer_memory_limits(context);
    const std::vector<BufferNeed> needs = buffer_needs(pixels);
    return std::all_of(needs.begin(), needs.end(), [&](const BufferNeed& need) { return gpu::fits(need, limits); });
}

void RefineSelection::start(const FloatImage& first, TraceResources& resources) {
    width_ = static_cast<std::uint32_t>(first.width);
    height_ = static_cast<std::uint32_t>(first.height);
    const std::size_t pixels = first.pixels.size();
    for (const BufferNeed& need : buffer_needs(pixels)) resources.working(need.binding, need.bytes);
    resources.working(BINDING_PICTURE, 0).write(first.pixels.data(), pixels * sizeof(vec4));
    const auto& levels = srgb8_level_starts();
    static_assert(sizeof(levels) == 256 * sizeof(uint));
    resources.working(BINDING_SRGB_LEVELS, 0).write(levels.data(), sizeof(levels));
    encoded_ = false;
    chosen_ = 0;
}

void RefineSelection::write_tables(double threshold, TraceResources& resources) {
    if (tables_for_ && *tables_for_ == threshold) return;
    const std::vector<std::uint32_t> floors = blue_difference_floors(threshold);
    if (floors.size() * sizeof(uint) > resource_need(BINDING_DIFFERENCE_FLOORS, 256 * 256).bytes)
        throw std::logic_error("the colour difference floors outgrew their buffer need");
    resources.working(BINDING_DIFFERENCE_FLOORS, 0).write(floors.data(), floors.size() * sizeof(uint));
    tables_for_ = threshold;
}

VkCommandBuffer RefineSelection::begin() const {
    VkCommandBuffer commands = submission_.begin();
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.handle());
    return commands;
}

void RefineSelection::record(VkCommandBuffer commands, const SelectStep& step, std::uint64_t items) const {
    compute_barrier(commands);
    vkCmdPushConstants(commands, layout_.pipeline_layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(step), &step);
    vkCmdDispatch(commands, static_cast<std::uint32_t>(std::max<std::uint64_t>(1, blocks_of(items))), 1, 1);
}

void RefineSelection::end_and_submit(const ProgressFn& progress, double done) const {
    compute_barrier(submission_.commands(), VK_ACCESS_HOST_READ_BIT, VK_PIPELINE_STAGE_HOST_BIT);
    submission_.end_and_wait(progress, done);
}

std::uint32_t RefineSelection::choose(double threshold, bool by_spread, TraceResources& resources,
                                      const ProgressFn& progress, double done) {
    write_tables(threshold, resources);
    const std::uint64_t pixels = std::uint64_t(width_) * height_;
    // pixels_to_refine's rule: a threshold of 0 or less takes every candidate.
    SelectStep step{SELECT_FLAG, width_, height_, threshold <= 0.0 ? 1u : 0u, 0, 0, by_spread ? 1u : 0u, 0};
    VkCommandBuffer commands = begin();
    VkDescriptorSet set = resources.descriptor_set();
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.pipeline_layout(), 0, 1, &set, 0, nullptr);
    if (!encoded_) {
        step.kind = SELECT_ENCODE;
        record(commands, step, pixels);
    }
    step.kind = SELECT_FLAG;
    record(commands, step, pixels);
    step.kind = SELECT_BLOCKS;
    record(commands, step, 1);
    step.kind = SELECT_SCATTER;
    record(commands, step, pixels);
    end_and_submit(progress, done);
    encoded_ = true;
    std::memcpy(&chosen_, static_cast<const uint*>(resources.working(BINDING_BLOCK_SUMS, 0).data()) + blocks_of(pixels),
                sizeof(chosen_));
    return chosen_;
}

void RefineSelection::merge(std::uint32_t first, std::uint32_t count, bool spread, TraceResources& resources,
                            const ProgressFn& progress, double done) {
    VkCommandBuffer commands = begin();
    VkDescriptorSet set = resources.descriptor_set();
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.pipeline_layout(), 0, 1, &set, 0, nullptr);
    record(commands, SelectStep{SELECT_MERGE, width_, height_, 0, first, count, spread ? 1u : 0u, 0}, count);
    end_and_submit(progress, done);
}

FloatImage RefineSelection::picture(TraceResources& resources) const {
    FloatImage image(static_cast<int>(width_), static_cast<int>(height_));
    std::memcpy(image.pixels.data(), resources.working(BINDING_PICTURE, 0).data(), image.pixels.size() * sizeof(vec4));
    return image;
}

std::vector<std::uint32_t> RefineSelection::list(TraceResources& resources) const {
    const auto* entries = static_cast<const uint*>(resources.working(BINDING_REFINE, 0).data());
    return {entries, entries + chosen_};
}

}  // namespace lancer::gpu

#pragma once
// Adaptive anti-aliasing's choice of the pixels to refine, made on the device
// (shaders/refine_select.comp): the picture stays there between the steps of a render, each
// choice is compacted into refine_list for the refining trace to dispatch over, and only its count
// comes back. The rule is the host's (pixels_to_refine in image/adaptive.hpp, the spread rule in
// render/adaptive_render.cpp), evaluated exactly from image/difference_tables.hpp's tables.
#include <cstdint>
#include <optional>
#include <vector>

#include "gpu/vulkan/context.hpp"
#include "gpu/layout.hpp"
#include "gpu/vulkan/memory_budget.hpp"
#include "gpu/vulkan/pipeline.hpp"
#include "gpu/vulkan/submit.hpp"
#include "gpu/trace_resources.hpp"
#include "image/image.hpp"
#include "render/renderer.hpp"

namespace lancer::gpu {

class RefineSelection {
public:
    RefineSelection(const Context& context, const TraceLayout& layout, const std::vector<std::uint32_t>& spirv);
    ~RefineSelection();
    RefineSelection(const RefineSelection&) = delete;
    RefineSelection& operator=(const RefineSelection&) = delete;

    // What the selection over a picture of `pixels` keeps on the device.
    static std::vector<BufferNeed> buffer_needs(std::uint64_t pixels);
    // Whether the device can: each of those buffers within its limits (maxStorageBufferRange: the
    // picture, 16 bytes a pixel, is the largest) and a workgroup per block of SELECT_BLOCK pixels
    // in one dispatch. Where not, the host chooses.
    static bool fits(std::uint64_t pixels, const Context& context);

    // Starts from a render's first picture (every pixel's first ray): it goes to the device, and
    // every pixel is a candidate for the first choice.
    void start(const FloatImage& first, TraceResources& resources);
    // Chooses, among the candidates (the last refinement's pixels, or every pixel after start()),
    // those that differ from a neighbour by more than `threshold` and, `by_spread`, those whose
    // samples spread by more in the last refinement (which merged them with their spread); lists
    // them in refine_list in increasing order and makes them the next candidates. Returns how many.
    std::uint32_t choose(double threshold, bool by_spread, TraceResources& resources, const ProgressFn& progress,
                         double done);
    // Merges entries [first, first + count) of the list, which a refining band has just traced into
    // the output buffer (with its samples' extremes after them when `spread`), into the picture.
    void merge(std::uint32_t first, std::uint32_t count, bool spread, TraceResources& resources,
               const ProgressFn& progress, double done);
    // The picture as it is now (rgb: each pixel's last colour; a: all its rays).
    FloatImage picture(TraceResources& resources) const;
    // The list the last choose() made (for tests: the host reads back only its count).
    std::vector<std::uint32_t> list(TraceResources& resources) const;

private:
    // Records `step` over `items` pixels or list entries (a workgroup per SELECT_BLOCK of them),
    // after a barrier against the steps before.
    void record(VkCommandBuffer commands, const SelectStep& step, std::uint64_t items) const;
    VkCommandBuffer begin() const;
    void end_and_submit(const ProgressFn& progress, double done) const;
    void write_tables(double threshold, TraceResources& resources);

    const Context& context_;
    const TraceLayout& layout_;
    ComputePipeline pipeline_;
    Submission submission_;
    std::uint32_t width_ = 0, height_ = 0;
    bool encoded_ = false;  // the codes of the picture start() gave are made
    std::uint32_t chosen_ = 0;
    std::optional<double> tables_for_;  // the threshold the difference table holds
};

}  // namespace lancer::gpu

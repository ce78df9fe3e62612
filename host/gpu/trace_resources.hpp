#pragma once
// The tracer's descriptor set and the buffers behind it, one per entry of LANCER_RESOURCES
// (shaders/layout.h): the frame's uniform block, a texel buffer per scene array, the output
// band. Everything about a resource (descriptor type, texel format, buffer usage, pool size,
// debug name) follows from its kind in that table.
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "gpu/vulkan/buffer.hpp"
#include "gpu/vulkan/context.hpp"
#include "gpu/layout.hpp"
#include "gpu/packing/scene_packing.hpp"

namespace lancer::gpu {

// What the last upload() copied to the GPU. Of each scene array only the bytes that differ from
// what the GPU already holds are written: an animation frame that only moves the camera writes
// the frame uniform and the view's direction grids (which come last in their arrays), one that
// moves lights writes the light array too.
struct UploadStats {
    std::size_t bytes_written = 0;  // what changed, frame uniform included
    std::size_t bytes_skipped = 0;  // what the buffers already held
    std::size_t bytes_moved = 0;    // what did not change, copied into a buffer that had to grow
};

class TraceResources {
public:
    TraceResources(const Context& context, VkDescriptorSetLayout set_layout);
    ~TraceResources();
    TraceResources(const TraceResources&) = delete;
    TraceResources& operator=(const TraceResources&) = delete;

    // Writes the frame parameters, and each packed array unless it is what its buffer holds.
    // Keeps `packed` to compare the next upload against (no copy of it).
    void upload(std::shared_ptr<const PackedScene> packed, const FrameParams& frame);
    void upload(const PackedScene& packed, const FrameParams& frame) {  // keeps a copy
        upload(std::make_shared<const PackedScene>(packed), frame);
    }
    // A scene uploaded once and never compared against (a still): each array is freed on the
    // host as soon as its buffer holds it, so that the two copies never coexist whole.
    void upload_releasing(PackedScene& packed, const FrameParams& frame);
    const UploadStats& last_upload() const { return last_upload_; }

    // The output band: at least `bytes`, mapped for reading back.
    const Buffer& output(std::size_t bytes);
    // The compact list of pixels a refining band traces (BandParams::refine_count).
    void write_refine_list(const uint* pixels, std::size_t count);

    // A buffer the passes themselves fill (photon mapping's, LANCER_PHOTON_BUFFERS): at least
    // `bytes`, mapped. Growing it keeps nothing of what it held.
    const Buffer& working(uint binding, std::size_t bytes);

    // The descriptor set, its writes brought up to date with the buffers.
    VkDescriptorSet descriptor_set();

private:
    // Makes the buffer of `binding` hold at least `bytes`; true when it was (re)made.
    bool reserve(uint binding, std::size_t bytes);
    void write_frame(const FrameParams& frame);

    const Context& context_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    std::array<Buffer, kResourceCount> buffers_;  // by binding
    // What the scene arrays' buffers hold, kept on the host to compare against (reading mapped
    // GPU memory back can be very slow on discrete GPUs): the scene last uploaded, shared with
    // the renderer that packed it.
    std::shared_ptr<const PackedScene> held_;
    bool descriptors_dirty_ = true;
    UploadStats last_upload_;
};

}  // namespace lancer::gpu

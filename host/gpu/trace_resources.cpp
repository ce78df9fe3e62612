#include "gpu/trace_resources.hpp"

#include <algorithm>
#include <cstring>

#include "core/page_release.hpp"
#include "gpu/vulkan/resource_kinds.hpp"
#include "gpu/vulkan/vk_check.hpp"

namespace lancer::gpu {
TraceResources::TraceResources(const Context& context, VkDescriptorSetLayout set_layout) : context_(context) {
    VkDevice device = context.device();
    std::vector<VkDescriptorPoolSize> sizes;
    for (const ResourceSpec& r : kResources) {
        VkDescriptorType type = descriptor_type(r.kind);
        auto same = std::find_if(sizes.begin(), sizes.end(), [&](const auto& s) { return s.type == type; });
        if (same == sizes.end()) sizes.push_back({type, 1});
        else ++same->descriptorCount;
    }
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    pool_info.pPoolSizes = sizes.data();
    VK_CHECK(vkCreateDescriptorPool(device, &pool_info, nullptr, &pool_));
    context.set_name(VK_OBJECT_TYPE_DESCRIPTOR_POOL, pool_, "tracer descriptors");
    VkDescriptorSetAllocateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    set_info.descriptorPool = pool_;
    set_info.descriptorSetCount = 1;
    set_info.pSetLayouts = &set_layout;
    try {
        VK_CHECK(vkAllocateDescriptorSets(device, &set_info, &set_));
    } catch (...) {
        vkDestroyDescriptorPool(device, pool_, nullptr);
        throw;
    }
    context.set_name(VK_OBJECT_TYPE_DESCRIPTOR_SET, set_, "tracer descriptors");
}

TraceResources::~TraceResources() {
    buffers_ = {};
    if (pool_) vkDestroyDescriptorPool(context_.device(), pool_, nullptr);
}

bool TraceResources::reserve(uint binding, std::size_t bytes) {
    const ResourceSpec& r = resource(binding);
    // At least one element: an empty buffer (or texel view) is invalid.
    bytes = std::max(bytes, r.element_bytes);
    Buffer& buffer = buffers_[binding];
    if (buffer.size() >= bytes) return false;
    buffer = Buffer(context_, bytes, buffer_usage(r.kind), r.name, texel_format(r.kind));
    descriptors_dirty_ = true;
    return true;
}

void TraceResources::upload(std::shared_ptr<const PackedScene> packed, const FrameParams& frame) {
    last_upload_ = {};
    for (std::size_t a = 0; a < kSceneArrayCount; ++a) {
        std::span<const std::byte> bytes = packed->bytes(SceneArray(a));
        const std::span<const std::byte> held = held_ ? held_->bytes(SceneArray(a)) : std::span<const std::byte>();
        const uint binding = kSceneArrays[a].binding;
        const bool grown = reserve(binding, bytes.size());
        // Only the elements from the first to the last that differ from what the buffer held:
        // where the scene's data comes first and the view's last (the direction grids), a new
        // camera rewrites only the view's. A buffer that had to grow gets the rest copied too.
        const std::size_t element = kSceneArrays[a].element_bytes;
        const std::size_t common = std::min(bytes.size(), held.size());
        std::size_t first = held.data() == bytes.data()  // the same scene again (a render's next step)
                                ? common
                                : std::mismatch(bytes.begin(), bytes.begin() + common, held.begin()).first - bytes.begin();
        std::size_t end = bytes.size();
        if (held.size() == bytes.size())
            while (end > first && bytes[end - 1] == held[end - 1]) --end;
        first = first / element * element;
        end = std::min(bytes.size(), (end + element - 1) / element * element);
        if (grown && !bytes.empty()) {
            buffers_[binding].write(bytes.data(), bytes.size());
            last_upload_.bytes_moved += bytes.size() - (end - first);
        } else {
            if (first < end) buffers_[binding].write(bytes.data() + first, end - first, first);
            last_upload_.bytes_skipped += bytes.size() - (end - first);
        }
        last_upload_.bytes_written += end - first;
    }
    held_ = std::move(packed);
    write_frame(frame);
}

void TraceResources::upload_releasing(PackedScene& packed, const FrameParams& frame) {
    last_upload_ = {};
    held_.reset();  // the buffers no longer hold it: the next upload writes every array
    for (std::size_t a = 0; a < kSceneArrayCount; ++a) {
        const std::span<const std::byte> bytes = packed.bytes(SceneArray(a));
        const uint binding = kSceneArrays[a].binding;
        reserve(binding, bytes.size());
        constexpr std::size_t kStep = std::size_t(2) << 20;
        const void* released = bytes.data();
        for (std::size_t done = 0; done < bytes.size(); done += kStep) {
            const std::size_t n = std::min(kStep, bytes.size() - done);
            buffers_[binding].write(bytes.data() + done, n, done);
            released = release_pages(released, bytes.data() + done + n);  // the host's copy, behind the device's
        }
        last_upload_.bytes_written += bytes.size();
        packed.release(SceneArray(a));
    }
    write_frame(frame);
}

void TraceResources::write_frame(const FrameParams& frame) {
    reserve(BINDING_FRAME, sizeof(frame));
    buffers_[BINDING_FRAME].write(&frame, sizeof(frame));
    last_upload_.bytes_written += sizeof(frame);
}

const Buffer& TraceResources::working(uint binding, std::size_t bytes) {
    reserve(binding, bytes);
    return buffers_[binding];
}

const Buffer& TraceResources::output(std::size_t bytes) {
    reserve(BINDING_OUTPUT, bytes);
    return buffers_[BINDING_OUTPUT];
}

void TraceResources::write_refine_list(const uint* pixels, std::size_t count) {
    reserve(BINDING_REFINE, count * sizeof(uint));
    if (count) buffers_[BINDING_REFINE].write(pixels, count * sizeof(uint));
}

VkDescriptorSet TraceResources::descriptor_set() {
    if (!descriptors_dirty_) return set_;
    std::array<VkDescriptorBufferInfo, kResourceCount> infos{};
    std::array<VkBufferView, kResourceCount> views{};
    std::array<VkWriteDescriptorSet, kResourceCount> writes{};
    for (std::size_t i = 0; i < kResourceCount; ++i) {
        const ResourceSpec& r = kResources[i];
        reserve(r.binding, 0);  // a resource nothing was written to yet still needs a valid buffer
        const Buffer& buffer = buffers_[r.binding];
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = set_;
        writes[i].dstBinding = r.binding;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = descriptor_type(r.kind);
        if (buffer.view()) {
            views[i] = buffer.view();
            writes[i].pTexelBufferView = &views[i];
        } else {
            infos[i] = {buffer.handle(), 0, VK_WHOLE_SIZE};
            writes[i].pBufferInfo = &infos[i];
        }
    }
    vkUpdateDescriptorSets(context_.device(), static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
    descriptors_dirty_ = false;
    return set_;
}

}  // namespace lancer::gpu

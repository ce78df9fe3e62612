#include "gpu/vulkan/buffer.hpp"

#include <utility>

#include "core/huge_pages.hpp"
#include "gpu/vulkan/vk_check.hpp"

namespace lancer::gpu {
namespace {

// Host-visible and coherent: mapped once, written and read directly. Cached memory makes reading
// the output back fast; device-local helps the GPU read scenes.
constexpr VkMemoryPropertyFlags kRequired = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
constexpr VkMemoryPropertyFlags kPreferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT | VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;

}  // namespace

DeviceMemoryLimits buffer_memory_limits(const Context& context) {
    const VkPhysicalDeviceMemoryProperties& memory = context.memory_properties();
    std::uint32_t type = context.memory_type(~0u, kRequired, kPreferred);
    return {context.info().name, context.limits().maxTexelBufferElements, context.limits().maxStorageBufferRange,
            memory.memoryHeaps[memory.memoryTypes[type].heapIndex].size};
}

Buffer::Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, const std::string& name,
               VkFormat view_format)
    : device_(context.device()), size_(size) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(device_, &info, nullptr, &buffer_));
    try {
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device_, buffer_, &req);
        const bool addressed = (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) != 0;
        VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
        flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.pNext = addressed ? &flags : nullptr;
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = context.memory_type(req.memoryTypeBits, kRequired, kPreferred);
        context.reserve_device_memory(req.size);
        VK_CHECK(vkAllocateMemory(device_, &alloc, nullptr, &memory_));
        VK_CHECK(vkBindBufferMemory(device_, buffer_, memory_, 0));
        VK_CHECK(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
        if (addressed) {
            VkBufferDeviceAddressInfo where{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
            where.buffer = buffer_;
            address_ = vkGetBufferDeviceAddress(device_, &where);
        }
        // lavapipe's memory is the process's own: a large buffer is filled faster in huge pages.
        if (size >= kHugeArrayBytes) advise_huge_pages(mapped_, size);
        context.set_name(VK_OBJECT_TYPE_BUFFER, buffer_, name);
        context.set_name(VK_OBJECT_TYPE_DEVICE_MEMORY, memory_, name);
        if (view_format != VK_FORMAT_UNDEFINED) {
            VkBufferViewCreateInfo view{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
            view.buffer = buffer_;
            view.format = view_format;
            view.range = VK_WHOLE_SIZE;
            VK_CHECK(vkCreateBufferView(device_, &view, nullptr, &view_));
            context.set_name(VK_OBJECT_TYPE_BUFFER_VIEW, view_, name);
        }
    } catch (...) {
        release();
        throw;
    }
}

Buffer::~Buffer() { release(); }

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        release();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
        size_ = std::exchange(other.size_, 0);
        address_ = std::exchange(other.address_, 0);
        mapped_ = std::exchange(other.mapped_, nullptr);
    }
    return *this;
}

void Buffer::release() noexcept {
    if (!device_) return;
    if (view_) vkDestroyBufferView(device_, view_, nullptr);
    if (mapped_) vkUnmapMemory(device_, memory_);
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
    buffer_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    view_ = VK_NULL_HANDLE;
    mapped_ = nullptr;
}

}  // namespace lancer::gpu

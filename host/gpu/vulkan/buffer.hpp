#pragma once
// A VkBuffer with its own host-visible, coherent memory, persistently mapped. lavapipe has one
// memory type that is device-local and host-visible, so no staging copies are needed there; on
// discrete GPUs this is system memory the GPU reads over the bus, which suits lancer's small
// scene buffers and one-band output buffer.
#include <cstddef>
#include <cstring>
#include <string>

#include "gpu/vulkan/context.hpp"
#include "gpu/vulkan/memory_budget.hpp"

namespace lancer::gpu {

// How large Buffers may get on this device: maxTexelBufferElements texels for texel buffers,
// maxStorageBufferRange for storage buffers (the shader binds each whole), and together the heap
// of the memory type they are made from.
DeviceMemoryLimits buffer_memory_limits(const Context& context);

class Buffer {
public:
    Buffer() = default;
    // `name` labels the buffer (and its view) in validation messages and debuggers. With a
    // `view_format`, the buffer also gets a VkBufferView of that format over all of it (a texel
    // buffer). With VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT in `usage`, it has a device address
    // (the device's bufferDeviceAddress feature enabled: bench/ray_query's).
    Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, const std::string& name,
           VkFormat view_format = VK_FORMAT_UNDEFINED);
    ~Buffer();
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    VkBuffer handle() const { return buffer_; }
    VkBufferView view() const { return view_; }
    VkDeviceSize size() const { return size_; }
    VkDeviceAddress address() const { return address_; }
    void* data() const { return mapped_; }
    void write(const void* src, std::size_t bytes, std::size_t offset = 0) const {
        std::memcpy(static_cast<char*>(mapped_) + offset, src, bytes);
    }

private:
    void release() noexcept;

    VkDevice device_ = VK_NULL_HANDLE;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkBufferView view_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    VkDeviceAddress address_ = 0;
    void* mapped_ = nullptr;
};

}  // namespace lancer::gpu

#pragma once
// A Vulkan 1.2 device with the driver's acceleration structures and ray queries switched on
// (bench/ray_query.sh). lancer's gpu::Context enables no device extensions, so the benchmark makes
// its own: the same choice of device (the most GPU-like), the same validation layer and message
// count, plus VK_KHR_acceleration_structure, VK_KHR_ray_query and buffer device addresses.
#include <cstdint>
#include <functional>
#include <string>

#include <vulkan/vulkan.h>

namespace lancer::bench {

// The extension's entry points, which the loader does not export: looked up on the device.
struct RayQueryFunctions {
    PFN_vkCreateAccelerationStructureKHR create_structure = nullptr;
    PFN_vkDestroyAccelerationStructureKHR destroy_structure = nullptr;
    PFN_vkGetAccelerationStructureBuildSizesKHR build_sizes = nullptr;
    PFN_vkCmdBuildAccelerationStructuresKHR build = nullptr;
    PFN_vkGetAccelerationStructureDeviceAddressKHR structure_address = nullptr;
};

// Validation messages the layer reported on any RayQueryDevice so far, teardown included (each
// also printed to stderr).
std::uint32_t validation_messages();

class RayQueryDevice {
public:
    // Throws lancer::UserError where no device offers ray queries.
    explicit RayQueryDevice(bool validation);
    ~RayQueryDevice();
    RayQueryDevice(const RayQueryDevice&) = delete;
    RayQueryDevice& operator=(const RayQueryDevice&) = delete;

    VkDevice device() const { return device_; }
    const RayQueryFunctions& functions() const { return functions_; }
    const std::string& description() const { return description_; }
    // Where a build's scratch memory may start: a multiple of this (a power of two).
    VkDeviceSize scratch_alignment() const { return scratch_alignment_; }
    std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required) const;
    // Records commands with `record`, submits them and waits: the host's wall seconds from
    // submission to the fence.
    double run(const std::function<void(VkCommandBuffer)>& record) const;

private:
    static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                      VkDebugUtilsMessageTypeFlagsEXT types,
                                                      const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);
    void release() noexcept;

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties memory_{};
    RayQueryFunctions functions_;
    std::string description_;
    VkDeviceSize scratch_alignment_ = 1;
};

// A buffer in host-visible, coherent memory (lavapipe's only kind), mapped, with its device
// address where `usage` asks for one.
class DeviceBuffer {
public:
    DeviceBuffer() = default;
    DeviceBuffer(const RayQueryDevice& device, VkDeviceSize size, VkBufferUsageFlags usage);
    ~DeviceBuffer();
    DeviceBuffer(DeviceBuffer&& other) noexcept;
    DeviceBuffer& operator=(DeviceBuffer&& other) noexcept;
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;

    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    VkDeviceAddress address() const { return address_; }
    void* data() const { return mapped_; }

private:
    void release() noexcept;

    VkDevice device_ = VK_NULL_HANDLE;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    VkDeviceAddress address_ = 0;
    void* mapped_ = nullptr;
};

}  // namespace lancer::bench

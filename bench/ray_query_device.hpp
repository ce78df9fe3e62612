#pragma once
// A Vulkan device with the driver's acceleration structures and ray queries switched on
// (bench/ray_query.sh): lancer's gpu::Context (the same choice of device, validation layer and
// message count) asked for VK_KHR_acceleration_structure, VK_KHR_ray_query and buffer device
// addresses, with a command buffer and a fence to run the benchmark's commands.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <vulkan/vulkan.h>

#include "gpu/vulkan/buffer.hpp"
#include "gpu/vulkan/context.hpp"

namespace lancer::bench {

// The extension's entry points, which the loader does not export: looked up on the device.
struct RayQueryFunctions {
    PFN_vkCreateAccelerationStructureKHR create_structure = nullptr;
    PFN_vkDestroyAccelerationStructureKHR destroy_structure = nullptr;
    PFN_vkGetAccelerationStructureBuildSizesKHR build_sizes = nullptr;
    PFN_vkCmdBuildAccelerationStructuresKHR build = nullptr;
    PFN_vkGetAccelerationStructureDeviceAddressKHR structure_address = nullptr;
};

class RayQueryDevice {
public:
    // Throws lancer::UserError where no device offers ray queries.
    explicit RayQueryDevice(bool validation);
    ~RayQueryDevice();
    RayQueryDevice(const RayQueryDevice&) = delete;
    RayQueryDevice& operator=(const RayQueryDevice&) = delete;

    VkDevice device() const { return context_->device(); }
    const RayQueryFunctions& functions() const { return functions_; }
    const std::string& description() const { return description_; }
    // Where a build's scratch memory may start: a multiple of this (a power of two).
    VkDeviceSize scratch_alignment() const { return scratch_alignment_; }
    // A buffer of `size` bytes (at least 4: an empty scene still binds its buffers), labelled
    // "ray query NAME".
    gpu::Buffer buffer(VkDeviceSize size, VkBufferUsageFlags usage, const std::string& name) const;
    // Records commands with `record`, submits them and waits: the host's wall seconds from
    // submission to the fence.
    double run(const std::function<void(VkCommandBuffer)>& record) const;

private:
    std::unique_ptr<gpu::Context> context_;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    RayQueryFunctions functions_;
    std::string description_;
    VkDeviceSize scratch_alignment_ = 1;
};

// A buffer in host-visible, coherent memory (lavapipe's only kind), mapped, with its device
// address where its usage asks for one: lancer's own.
using DeviceBuffer = gpu::Buffer;

}  // namespace lancer::bench

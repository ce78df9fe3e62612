#include "ray_query_device.hpp"

#include <algorithm>
#include <chrono>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "gpu/vulkan/vk_check.hpp"

namespace lancer::bench {
namespace {

template <class F>
F device_function(VkDevice device, const char* name) {
    auto f = reinterpret_cast<F>(vkGetDeviceProcAddr(device, name));
    if (!f) throw UserError(std::string("the Vulkan driver does not provide ") + name);
    return f;
}

}  // namespace

RayQueryDevice::RayQueryDevice(bool validation) {
    // The three features the benchmark needs, beside lancer's own.
    VkPhysicalDeviceRayQueryFeaturesKHR query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
    query.rayQuery = VK_TRUE;
    VkPhysicalDeviceAccelerationStructureFeaturesKHR structure{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    structure.accelerationStructure = VK_TRUE;
    structure.pNext = &query;
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    v12.bufferDeviceAddress = VK_TRUE;
    v12.pNext = &structure;
    gpu::ContextOptions options{"", validation};
    options.device_extensions = {VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME, VK_KHR_RAY_QUERY_EXTENSION_NAME,
                                 VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
    options.device_features = &v12;  // a device with the extensions has the features (the extensions require them)
    context_ = std::make_unique<gpu::Context>(options);
    VkDevice device = context_->device();

    VkPhysicalDeviceAccelerationStructurePropertiesKHR structure_props{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props.pNext = &structure_props;
    vkGetPhysicalDeviceProperties2(context_->physical_device(), &props);
    scratch_alignment_ = std::max<VkDeviceSize>(1, structure_props.minAccelerationStructureScratchOffsetAlignment);
    description_ = context_->info().name + " (" + context_->info().driver + ")";

    functions_.create_structure = device_function<PFN_vkCreateAccelerationStructureKHR>(device, "vkCreateAccelerationStructureKHR");
    functions_.destroy_structure = device_function<PFN_vkDestroyAccelerationStructureKHR>(device, "vkDestroyAccelerationStructureKHR");
    functions_.build_sizes =
        device_function<PFN_vkGetAccelerationStructureBuildSizesKHR>(device, "vkGetAccelerationStructureBuildSizesKHR");
    functions_.build = device_function<PFN_vkCmdBuildAccelerationStructuresKHR>(device, "vkCmdBuildAccelerationStructuresKHR");
    functions_.structure_address =
        device_function<PFN_vkGetAccelerationStructureDeviceAddressKHR>(device, "vkGetAccelerationStructureDeviceAddressKHR");

    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = context_->command_pool();
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(device, &alloc, &commands_));
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(device, &fence_info, nullptr, &fence_));
}

RayQueryDevice::~RayQueryDevice() {
    VkDevice device = context_->device();
    vkDeviceWaitIdle(device);
    if (fence_) vkDestroyFence(device, fence_, nullptr);
    if (commands_) vkFreeCommandBuffers(device, context_->command_pool(), 1, &commands_);
}

double RayQueryDevice::run(const std::function<void(VkCommandBuffer)>& record) const {
    VK_CHECK(vkResetCommandBuffer(commands_, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands_, &begin));
    record(commands_);
    VK_CHECK(vkEndCommandBuffer(commands_));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands_;
    VkDevice device = context_->device();
    VK_CHECK(vkResetFences(device, 1, &fence_));
    const auto start = std::chrono::steady_clock::now();
    VK_CHECK(vkQueueSubmit(context_->queue(), 1, &submit, fence_));
    VK_CHECK(vkWaitForFences(device, 1, &fence_, VK_TRUE, UINT64_MAX));
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

DeviceBuffer::DeviceBuffer(const RayQueryDevice& device, VkDeviceSize size, VkBufferUsageFlags usage)
    : device_(device.device()), size_(size) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = std::max<VkDeviceSize>(size, 4);  // an empty scene still binds its buffers
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(device_, &info, nullptr, &buffer_));
    try {
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device_, buffer_, &req);
        const bool addressed = usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
        VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
        flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.pNext = addressed ? &flags : nullptr;
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = device.memory_type(
            req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        VK_CHECK(vkAllocateMemory(device_, &alloc, nullptr, &memory_));
        VK_CHECK(vkBindBufferMemory(device_, buffer_, memory_, 0));
        VK_CHECK(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
        if (addressed) {
            VkBufferDeviceAddressInfo where{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
            where.buffer = buffer_;
            address_ = vkGetBufferDeviceAddress(device_, &where);
        }
    } catch (...) {
        release();
        throw;
    }
}

DeviceBuffer::~DeviceBuffer() { release(); }

DeviceBuffer::DeviceBuffer(DeviceBuffer&& other) noexcept { *this = std::move(other); }

DeviceBuffer& DeviceBuffer::operator=(DeviceBuffer&& other) noexcept {
    if (this != &other) {
        release();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        size_ = std::exchange(other.size_, 0);
        address_ = std::exchange(other.address_, 0);
        mapped_ = std::exchange(other.mapped_, nullptr);
    }
    return *this;
}

void DeviceBuffer::release() noexcept {
    if (!device_) return;
    if (mapped_) vkUnmapMemory(device_, memory_);
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
    buffer_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    mapped_ = nullptr;
    device_ = VK_NULL_HANDLE;
}

}  // namespace lancer::bench

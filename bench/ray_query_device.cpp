#include "ray_query_device.hpp"

#include <algorithm>
#include <chrono>

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

gpu::Buffer RayQueryDevice::buffer(VkDeviceSize size, VkBufferUsageFlags usage, const std::string& name) const {
    return gpu::Buffer(*context_, std::max<VkDeviceSize>(size, 4), usage, "ray query " + name);
}

}  // namespace lancer::bench

#include "ray_query_device.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "gpu/vulkan/vk_check.hpp"

namespace lancer::bench {
namespace {

std::atomic<std::uint32_t> g_messages{0};  // the layer may call back from any thread

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kDeviceExtensions[] = {VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME, VK_KHR_RAY_QUERY_EXTENSION_NAME,
                                             VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};

bool has_extensions(VkPhysicalDevice device) {
    std::uint32_t count = 0;
    VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> available(count);
    VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, available.data()));
    return std::all_of(std::begin(kDeviceExtensions), std::end(kDeviceExtensions), [&](const char* wanted) {
        return std::any_of(available.begin(), available.end(),
                           [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, wanted) == 0; });
    });
}

// Real GPUs before lavapipe, as lancer's own context chooses.
int preference(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
        default: return 0;
    }
}

template <class F>
F device_function(VkDevice device, const char* name) {
    auto f = reinterpret_cast<F>(vkGetDeviceProcAddr(device, name));
    if (!f) throw UserError(std::string("the Vulkan driver does not provide ") + name);
    return f;
}

}  // namespace

std::uint32_t validation_messages() { return g_messages.load(); }

RayQueryDevice::RayQueryDevice(bool validation) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "lancer ray query benchmark";
    app.apiVersion = VK_API_VERSION_1_2;
    std::vector<const char*> layers, extensions;
    if (validation) {
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    VkInstanceCreateInfo instance_info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    instance_info.pApplicationInfo = &app;
    instance_info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    instance_info.ppEnabledLayerNames = layers.data();
    instance_info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    instance_info.ppEnabledExtensionNames = extensions.data();
    VK_CHECK(vkCreateInstance(&instance_info, nullptr, &instance_));
    try {
        if (validation) {
            VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
            info.messageSeverity =
                VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
            info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
            info.pfnUserCallback = &RayQueryDevice::on_message;
            info.pUserData = this;
            auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
            if (!create) throw UserError("the validation layer does not provide VK_EXT_debug_utils");
            VK_CHECK(create(instance_, &info, nullptr, &messenger_));
        }

        std::uint32_t count = 0;
        VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, nullptr));
        std::vector<VkPhysicalDevice> devices(count);
        VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, devices.data()));
        int best = -1;
        for (VkPhysicalDevice d : devices) {
            VkPhysicalDeviceProperties props;
            vkGetPhysicalDeviceProperties(d, &props);
            if (has_extensions(d) && preference(props.deviceType) > best) {
                best = preference(props.deviceType);
                physical_ = d;
            }
        }
        if (!physical_) throw UserError("no Vulkan device offers VK_KHR_acceleration_structure and VK_KHR_ray_query");

        VkPhysicalDeviceAccelerationStructurePropertiesKHR structure_props{
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
        VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
        driver.pNext = &structure_props;
        VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
        props.pNext = &driver;
        vkGetPhysicalDeviceProperties2(physical_, &props);
        scratch_alignment_ = std::max<VkDeviceSize>(1, structure_props.minAccelerationStructureScratchOffsetAlignment);
        description_ = std::string(props.properties.deviceName) + " (" + driver.driverName + " " + driver.driverInfo + ")";
        vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);

        // What the device offers, then exactly the three features the benchmark needs.
        VkPhysicalDeviceRayQueryFeaturesKHR query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
        VkPhysicalDeviceAccelerationStructureFeaturesKHR structure{
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
        VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
        structure.pNext = &query;
        v12.pNext = &structure;
        VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        supported.pNext = &v12;
        vkGetPhysicalDeviceFeatures2(physical_, &supported);
        if (!query.rayQuery || !structure.accelerationStructure || !v12.bufferDeviceAddress)
            throw UserError("the Vulkan device lacks rayQuery, accelerationStructure or bufferDeviceAddress");
        VkPhysicalDeviceRayQueryFeaturesKHR enable_query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
        enable_query.rayQuery = VK_TRUE;
        VkPhysicalDeviceAccelerationStructureFeaturesKHR enable_structure{
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
        enable_structure.accelerationStructure = VK_TRUE;
        enable_structure.pNext = &enable_query;
        VkPhysicalDeviceVulkan12Features enable_v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
        enable_v12.bufferDeviceAddress = VK_TRUE;
        enable_v12.pNext = &enable_structure;
        VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        enable.pNext = &enable_v12;

        std::uint32_t family_count = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(physical_, &family_count, nullptr);
        std::vector<VkQueueFamilyProperties> families(family_count);
        vkGetPhysicalDeviceQueueFamilyProperties(physical_, &family_count, families.data());
        std::uint32_t family = 0;
        while (family < family_count && !(families[family].queueFlags & VK_QUEUE_COMPUTE_BIT)) ++family;
        if (family == family_count) throw UserError("the ray query device has no compute queue");

        float priority = 1.0f;
        VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queue_info.queueFamilyIndex = family;
        queue_info.queueCount = 1;
        queue_info.pQueuePriorities = &priority;
        VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        device_info.pNext = &enable;
        device_info.queueCreateInfoCount = 1;
        device_info.pQueueCreateInfos = &queue_info;
        device_info.enabledExtensionCount = static_cast<std::uint32_t>(std::size(kDeviceExtensions));
        device_info.ppEnabledExtensionNames = kDeviceExtensions;
        VK_CHECK(vkCreateDevice(physical_, &device_info, nullptr, &device_));
        vkGetDeviceQueue(device_, family, 0, &queue_);

        functions_.create_structure =
            device_function<PFN_vkCreateAccelerationStructureKHR>(device_, "vkCreateAccelerationStructureKHR");
        functions_.destroy_structure =
            device_function<PFN_vkDestroyAccelerationStructureKHR>(device_, "vkDestroyAccelerationStructureKHR");
        functions_.build_sizes =
            device_function<PFN_vkGetAccelerationStructureBuildSizesKHR>(device_, "vkGetAccelerationStructureBuildSizesKHR");
        functions_.build =
            device_function<PFN_vkCmdBuildAccelerationStructuresKHR>(device_, "vkCmdBuildAccelerationStructuresKHR");
        functions_.structure_address = device_function<PFN_vkGetAccelerationStructureDeviceAddressKHR>(
            device_, "vkGetAccelerationStructureDeviceAddressKHR");

        VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        pool_info.queueFamilyIndex = family;
        VK_CHECK(vkCreateCommandPool(device_, &pool_info, nullptr, &pool_));
        VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        alloc.commandPool = pool_;
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &commands_));
        VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(device_, &fence_info, nullptr, &fence_));
    } catch (...) {
        release();
        throw;
    }
}

RayQueryDevice::~RayQueryDevice() { release(); }

void RayQueryDevice::release() noexcept {
    if (device_) {
        vkDeviceWaitIdle(device_);
        if (fence_) vkDestroyFence(device_, fence_, nullptr);
        if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
        vkDestroyDevice(device_, nullptr);
        device_ = VK_NULL_HANDLE;
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(instance_, messenger_, nullptr);
        messenger_ = VK_NULL_HANDLE;
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
}

std::uint32_t RayQueryDevice::memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required) const {
    for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
        if ((type_bits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & required) == required) return i;
    throw UserError("the ray query device has no host-visible, coherent memory");
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
    VK_CHECK(vkResetFences(device_, 1, &fence_));
    const auto start = std::chrono::steady_clock::now();
    VK_CHECK(vkQueueSubmit(queue_, 1, &submit, fence_));
    VK_CHECK(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

VKAPI_ATTR VkBool32 VKAPI_CALL RayQueryDevice::on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                           VkDebugUtilsMessageTypeFlagsEXT,
                                                           const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    ++g_messages;
    const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
    std::fprintf(stderr, "ray query: vulkan validation %s: %s\n", level, data->pMessage ? data->pMessage : "");
    return VK_FALSE;
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

#include "gpu/vulkan/context.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "core/error.hpp"
#include "core/process_limits.hpp"
#include "gpu/vulkan/driver_quirks.hpp"
#include "gpu/vulkan/pin_loaded_libraries.hpp"
#include "gpu/vulkan/vk_check.hpp"

namespace lancer::gpu {
namespace {

std::atomic<std::uint32_t> g_validation_messages{0};

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

const char* type_name(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
        default: return "other";
    }
}

// Real GPUs first, lavapipe (a CPU device) last.
int preference(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
        default: return 0;
    }
}

const char* kNoDevice =
    "no Vulkan device found: install a Vulkan driver (Debian: mesa-vulkan-drivers provides lavapipe, "
    "which runs on any CPU), or render with --backend cpu";

VkInstance create_instance(bool validation, bool& has_debug_utils) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "lancer";
    app.apiVersion = VK_API_VERSION_1_2;

    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    has_debug_utils = false;
    if (validation) {
        std::uint32_t count = 0;
        VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
        std::vector<VkLayerProperties> available(count);
        VK_CHECK(vkEnumerateInstanceLayerProperties(&count, available.data()));
        bool found = std::any_of(available.begin(), available.end(),
                                 [](const VkLayerProperties& l) { return std::strcmp(l.layerName, kValidationLayer) == 0; });
        if (!found)
            throw UserError("Vulkan validation was requested but VK_LAYER_KHRONOS_validation is not installed "
                            "(Debian: apt-get install vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        has_debug_utils = true;
    }
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkInstance instance = VK_NULL_HANDLE;
    VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER) throw UserError(kNoDevice);
    VK_CHECK(result);
    return instance;
}

std::vector<VkPhysicalDevice> physical_devices(VkInstance instance) {
    std::uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
    devices.resize(count);
    return devices;
}

std::optional<std::uint32_t> compute_queue_family(VkPhysicalDevice device) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (std::uint32_t i = 0; i < count; ++i)
        if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) return i;
    return std::nullopt;
}

DeviceInfo describe(VkPhysicalDevice device, std::uint32_t index) {
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props.pNext = &driver;
    vkGetPhysicalDeviceProperties2(device, &props);
    std::string driver_text = driver.driverName;
    if (driver.driverInfo[0]) driver_text += std::string(" ") + driver.driverInfo;
    return {index, props.properties.deviceName, type_name(props.properties.deviceType), driver_text, driver.driverID};
}

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

// The first of `extensions` that `device` does not offer, or none.
std::optional<std::string> missing_extension(VkPhysicalDevice device, const std::vector<const char*>& extensions) {
    if (extensions.empty()) return std::nullopt;  // lancer's own tracer: nothing to ask the driver at start-up
    std::uint32_t count = 0;
    VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> offered(count);
    VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, offered.data()));
    for (const char* wanted : extensions)
        if (std::none_of(offered.begin(), offered.end(),
                         [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, wanted) == 0; }))
            return wanted;
    return std::nullopt;
}

// Picks by index or name fragment when asked, otherwise the most GPU-like device with compute;
// either way one that offers `extensions`.
std::uint32_t choose_device(const std::vector<VkPhysicalDevice>& devices, const std::string& wanted,
                            const std::vector<const char*>& extensions) {
    if (devices.empty()) throw UserError(kNoDevice);
    if (!wanted.empty()) {
        bool numeric = std::all_of(wanted.begin(), wanted.end(), [](unsigned char c) { return std::isdigit(c); });
        std::string names;
        for (std::uint32_t i = 0; i < devices.size(); ++i) {
            DeviceInfo info = describe(devices[i], i);
            names += (names.empty() ? "" : "; ") + std::to_string(i) + ": " + info.name;
            bool match = numeric ? std::to_string(i) == wanted
                                 : lowercase(info.name).find(lowercase(wanted)) != std::string::npos;
            if (match) {
                if (!compute_queue_family(devices[i])) throw UserError("device '" + info.name + "' has no compute queue");
                if (auto missing = missing_extension(devices[i], extensions))
                    throw UserError("device '" + info.name + "' does not offer " + *missing);
                return i;
            }
        }
        throw UserError("no Vulkan device matches '" + wanted + "' (available: " + names + ")");
    }
    std::optional<std::uint32_t> best;
    int best_score = -1;
    for (std::uint32_t i = 0; i < devices.size(); ++i) {
        if (!compute_queue_family(devices[i]) || missing_extension(devices[i], extensions)) continue;
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(devices[i], &props);
        if (preference(props.deviceType) > best_score) {
            best_score = preference(props.deviceType);
            best = i;
        }
    }
    if (!best) {
        std::string needed = "a compute queue";
        for (const char* e : extensions) needed += std::string(", ") + e;
        throw UserError("no Vulkan device with " + needed + " found");
    }
    return *best;
}

}  // namespace

std::uint32_t validation_message_count() { return g_validation_messages.load(); }

void forget_validation_messages(std::uint32_t count) { g_validation_messages.fetch_sub(count); }

int exit_code_after_validation(int code) {
    std::uint32_t n = validation_message_count();
    if (!n) return code;
    std::fprintf(stderr, "lancer: error: %u Vulkan validation message(s)\n", n);
    return 1;
}

bool validation_requested_by_environment() {
    const char* v = std::getenv("LANCER_VALIDATION");
    return v && std::strcmp(v, "0") != 0 && v[0] != '\0';
}

std::vector<DeviceInfo> Context::list_devices() {
    bool unused = false;
    VkInstance instance = create_instance(false, unused);
    std::vector<DeviceInfo> result;
    try {
        auto devices = physical_devices(instance);
        for (std::uint32_t i = 0; i < devices.size(); ++i) result.push_back(describe(devices[i], i));
    } catch (...) {
        pin_loaded_libraries();
        vkDestroyInstance(instance, nullptr);
        throw;
    }
    pin_loaded_libraries();
    vkDestroyInstance(instance, nullptr);
    return result;
}

Context::Context(const ContextOptions& options) {
    bool debug_utils = false;
    instance_ = create_instance(options.validation, debug_utils);
    try {
        if (debug_utils) {
            VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
            // Warnings and errors only: INFO floods the log with loader chatter.
            info.messageSeverity =
                VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
            info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
            info.pfnUserCallback = &Context::on_validation_message;
            info.pUserData = this;
            auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
                vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
            if (!create) throw UserError("the validation layer does not provide VK_EXT_debug_utils");
            VK_CHECK(create(instance_, &info, nullptr, &messenger_));
        }

        auto devices = physical_devices(instance_);
        std::uint32_t index = choose_device(devices, options.device, options.device_extensions);
        physical_ = devices[index];
        info_ = describe(physical_, index);
        memory_in_a_file_ = keeps_device_memory_in_a_file(info_);
        reserve_device_memory(0);  // the driver's own allocations come first
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(physical_, &props);
        limits_ = props.limits;
        vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
        queue_family_ = *compute_queue_family(physical_);

        float priority = 1.0f;
        VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queue_info.queueFamilyIndex = queue_family_;
        queue_info.queueCount = 1;
        queue_info.pQueuePriorities = &priority;
        VkPhysicalDeviceFeatures supported{};
        vkGetPhysicalDeviceFeatures(physical_, &supported);
        VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        enabled.pNext = options.device_features;
        enabled.features.shaderFloat64 = supported.shaderFloat64;  // where there, implicit surfaces use it (surface_codegen)
        float64_ = supported.shaderFloat64 == VK_TRUE;
        VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        device_info.pNext = &enabled;
        device_info.queueCreateInfoCount = 1;
        device_info.pQueueCreateInfos = &queue_info;
        device_info.enabledExtensionCount = static_cast<std::uint32_t>(options.device_extensions.size());
        device_info.ppEnabledExtensionNames = options.device_extensions.data();
        VK_CHECK(vkCreateDevice(physical_, &device_info, nullptr, &device_));
        vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
        if (debug_utils)
            set_object_name_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
                vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));

        VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        pool_info.queueFamilyIndex = queue_family_;
        VK_CHECK(vkCreateCommandPool(device_, &pool_info, nullptr, &command_pool_));
        set_name(VK_OBJECT_TYPE_COMMAND_POOL, command_pool_, "commands");
        set_name(VK_OBJECT_TYPE_QUEUE, queue_, "compute queue");
        set_name(VK_OBJECT_TYPE_DEVICE, device_, info_.name);
    } catch (...) {
        release();
        throw;
    }
}

Context::~Context() { release(); }

void Context::reserve_device_memory(VkDeviceSize bytes) const {
    if (!memory_in_a_file_) return;
    std::lock_guard lock(file_memory_mutex_);
    reserve_file_backed_memory(file_memory_allocated_, bytes, file_size_limit());
}

void Context::set_name_of(VkObjectType type, std::uint64_t handle, const std::string& name) const {
    if (!set_object_name_ || !handle) return;
    const std::string label = "lancer " + name;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = label.c_str();
    set_object_name_(device_, &info);
}

void Context::release() noexcept {
    if (device_) {
        vkDeviceWaitIdle(device_);
        if (command_pool_) vkDestroyCommandPool(device_, command_pool_, nullptr);
        vkDestroyDevice(device_, nullptr);
        device_ = VK_NULL_HANDLE;
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(instance_, messenger_, nullptr);
        messenger_ = VK_NULL_HANDLE;
    }
    if (instance_) {
        pin_loaded_libraries();
        vkDestroyInstance(instance_, nullptr);
        instance_ = VK_NULL_HANDLE;
    }
}

std::uint32_t Context::memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required,
                                   VkMemoryPropertyFlags preferred) const {
    std::optional<std::uint32_t> best;
    int best_score = -1;
    for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
        if (!(type_bits & (1u << i))) continue;
        VkMemoryPropertyFlags flags = memory_.memoryTypes[i].propertyFlags;
        if ((flags & required) != required) continue;
        int score = __builtin_popcount(flags & preferred);
        if (score > best_score) {
            best_score = score;
            best = i;
        }
    }
    if (!best) throw VulkanError(VK_ERROR_FEATURE_NOT_PRESENT, "the Vulkan device has no suitable memory type");
    return *best;
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                               VkDebugUtilsMessageTypeFlagsEXT,
                                                               const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                               void*) {
    g_validation_messages.fetch_add(1);
    const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
    std::fprintf(stderr, "lancer: vulkan validation %s: %s\n", level, data->pMessage ? data->pMessage : "");
    return VK_FALSE;
}

}  // namespace lancer::gpu

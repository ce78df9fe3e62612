#pragma once
// A headless Vulkan compute context: instance (optionally with the Khronos validation layer),
// one physical device, one compute queue. No window, no surface.
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace lancer::gpu {

struct DeviceInfo {
    std::uint32_t index;
    std::string name;
    std::string type;  // "discrete GPU", "integrated GPU", "virtual GPU", "CPU", "other"
    std::string driver;
    VkDriverId driver_id = static_cast<VkDriverId>(0);
};

struct ContextOptions {
    std::string device;       // "" = best available; otherwise an index or part of the name
    bool validation = false;  // enable VK_LAYER_KHRONOS_validation and count its messages
};

// Validation messages (warnings and errors) seen by any context of this process so far, teardown
// included; each is also printed to stderr.
std::uint32_t validation_message_count();
// For tests that provoke a message on purpose to prove the layer is active.
void forget_validation_messages(std::uint32_t count);

// True when LANCER_VALIDATION=1 is set: how tests and CI turn the validation layer on.
bool validation_requested_by_environment();

class Context {
public:
    explicit Context(const ContextOptions& options);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    // All devices the loader reports, in the order --device INDEX refers to them.
    static std::vector<DeviceInfo> list_devices();

    VkDevice device() const { return device_; }
    VkPhysicalDevice physical_device() const { return physical_; }
    VkQueue queue() const { return queue_; }
    std::uint32_t queue_family() const { return queue_family_; }
    VkCommandPool command_pool() const { return command_pool_; }
    const DeviceInfo& info() const { return info_; }
    const VkPhysicalDeviceLimits& limits() const { return limits_; }
    const VkPhysicalDeviceMemoryProperties& memory_properties() const { return memory_; }

    // A memory type with all of `required` flags (and as many of `preferred` as possible).
    std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required,
                              VkMemoryPropertyFlags preferred) const;


private:
    void release() noexcept;
    static VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                                 VkDebugUtilsMessageTypeFlagsEXT types,
                                                                 const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                                 void* self);

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    std::uint32_t queue_family_ = 0;
    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    DeviceInfo info_;
    VkPhysicalDeviceLimits limits_{};
    VkPhysicalDeviceMemoryProperties memory_{};
};

}  // namespace lancer::gpu

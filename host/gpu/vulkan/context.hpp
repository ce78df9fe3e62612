#pragma once
// A headless Vulkan compute context: instance (optionally with the Khronos validation layer),
// one physical device, one compute queue. No window, no surface.
#include <atomic>
#include <cstdint>
#include <mutex>
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
    // Device extensions to enable: only a device that offers all of them is chosen (lancer's
    // tracer needs none; bench/ray_query's device needs the driver's ray queries).
    std::vector<const char*> device_extensions;
    // Features to enable beside lancer's own: a chain of feature structs (VkPhysicalDeviceVulkan12Features,
    // ...) that becomes the pNext of the device's VkPhysicalDeviceFeatures2; read only while the
    // context is made.
    void* device_features = nullptr;
};

// Validation messages (warnings and errors) seen by any context of this process so far, teardown
// included; each is also printed to stderr.
std::uint32_t validation_message_count();
// For tests that provoke a message on purpose to prove the layer is active.
void forget_validation_messages(std::uint32_t count);

// The exit code of a run that would end with `code`: 1, with one line on stderr, when the
// validation layer reported anything during the run. Release every Vulkan object first, so that
// teardown is checked too.
int exit_code_after_validation(int code);

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
    // Whether shaders may use double precision (the device's shaderFloat64, enabled when there).
    bool float64() const { return float64_; }

    // A memory type with all of `required` flags (and as many of `preferred` as possible).
    std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags required,
                              VkMemoryPropertyFlags preferred) const;

    // Labels a Vulkan object, so that validation messages (and debuggers) say which buffer or
    // pipeline they mean: "lancer PRIMITIVES". Does nothing without VK_EXT_debug_utils, which the
    // context enables with validation.
    // Called before each allocation of device memory: throws UserError where the driver keeps
    // device memory in a file that the process's file size limit would cut short (driver_quirks).
    void reserve_device_memory(VkDeviceSize bytes) const;

    template <class Handle>
    void set_name(VkObjectType type, Handle handle, const std::string& name) const {
        set_name_of(type, (std::uint64_t)handle, name);
    }

private:
    void release() noexcept;
    void set_name_of(VkObjectType type, std::uint64_t handle, const std::string& name) const;
    static VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                                 VkDebugUtilsMessageTypeFlagsEXT types,
                                                                 const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                                 void* self);

    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    PFN_vkSetDebugUtilsObjectNameEXT set_object_name_ = nullptr;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    std::uint32_t queue_family_ = 0;
    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    DeviceInfo info_;
    VkPhysicalDeviceLimits limits_{};
    VkPhysicalDeviceMemoryProperties memory_{};
    bool memory_in_a_file_ = false;
    bool float64_ = false;
    mutable std::mutex file_memory_mutex_;
    mutable std::uint64_t file_memory_allocated_ = 0;
};

}  // namespace lancer::gpu

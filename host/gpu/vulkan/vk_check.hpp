#pragma once
// Every Vulkan call goes through VK_CHECK: a failure becomes a VulkanError naming the VkResult,
// the call and the source location (a GpuOutOfMemory when the driver is out of memory).
#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

#include "core/error.hpp"

namespace lancer::gpu {

class VulkanError : public std::runtime_error {
public:
    VulkanError(VkResult result, const std::string& message) : std::runtime_error(message), result_(result) {}
    VkResult result() const { return result_; }

private:
    VkResult result_;
};

// The driver ran out of device or host memory: the scene or the image is too large for this
// machine, which the user can change (exit code 2), unlike a lost device or a bug.
class GpuOutOfMemory : public UserError {
public:
    using UserError::UserError;
};

const char* result_name(VkResult result);

[[noreturn]] void throw_vulkan_error(VkResult result, const char* call, const char* file, int line);

}  // namespace lancer::gpu

#define VK_CHECK(call)                                                                     \
    do {                                                                                   \
        VkResult vk_check_result_ = (call);                                                \
        if (vk_check_result_ != VK_SUCCESS)                                                \
            ::lancer::gpu::throw_vulkan_error(vk_check_result_, #call, __FILE__, __LINE__); \
    } while (0)

#include "gpu/vulkan/vk_check.hpp"

#include <filesystem>

namespace lancer::gpu {

const char* result_name(VkResult result) {
    switch (result) {
#define LANCER_RESULT(r) case r: return #r;
        LANCER_RESULT(VK_SUCCESS)
        LANCER_RESULT(VK_NOT_READY)
        LANCER_RESULT(VK_TIMEOUT)
        LANCER_RESULT(VK_EVENT_SET)
        LANCER_RESULT(VK_EVENT_RESET)
        LANCER_RESULT(VK_INCOMPLETE)
        LANCER_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        LANCER_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        LANCER_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        LANCER_RESULT(VK_ERROR_DEVICE_LOST)
        LANCER_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        LANCER_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        LANCER_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        LANCER_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        LANCER_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        LANCER_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        LANCER_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        LANCER_RESULT(VK_ERROR_FRAGMENTED_POOL)
        LANCER_RESULT(VK_ERROR_UNKNOWN)
        LANCER_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        LANCER_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        LANCER_RESULT(VK_ERROR_FRAGMENTATION)
        LANCER_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        LANCER_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
#undef LANCER_RESULT
        default: return "VkResult(unknown)";
    }
}

void throw_vulkan_error(VkResult result, const char* call, const char* file, int line) {
    std::string where = std::filesystem::path(file).filename().string() + ":" + std::to_string(line);
    std::string message = std::string("Vulkan call failed with ") + result_name(result) + ": " + call + " (" + where + ")";
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        throw GpuOutOfMemory("the GPU ran out of memory (" + message +
                             "): render a smaller image or a smaller scene, or with --backend cpu");
    if (result == VK_ERROR_DEVICE_LOST) message += "; the GPU driver reset or crashed (device lost)";
    throw VulkanError(result, message);
}

}  // namespace lancer::gpu

#include "gpu/vulkan/resource_kinds.hpp"

#include <stdexcept>

namespace lancer::gpu {

VkDescriptorType descriptor_type(uint kind) {
    switch (kind) {
        case RESOURCE_UNIFORM: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        case RESOURCE_OUTPUT: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        case RESOURCE_ROWS:
        case RESOURCE_UINT:
        case RESOURCE_INT: return VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    }
    throw std::logic_error("descriptor_type: unknown resource kind");
}

VkFormat texel_format(uint kind) {
    switch (kind) {
        case RESOURCE_ROWS: return VK_FORMAT_R32G32B32A32_UINT;
        case RESOURCE_UINT: return VK_FORMAT_R32_UINT;
        case RESOURCE_INT: return VK_FORMAT_R32_SINT;
        default: return VK_FORMAT_UNDEFINED;
    }
}

VkBufferUsageFlags buffer_usage(uint kind) {
    switch (kind) {
        case RESOURCE_UNIFORM: return VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
        case RESOURCE_OUTPUT: return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        default: return VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    }
}

}  // namespace lancer::gpu

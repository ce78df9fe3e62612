#pragma once
// The Vulkan side of a resource kind of shaders/layout.h (RESOURCE_*): its descriptor type,
// the format of its texel view and the usage of its buffer.
#include <vulkan/vulkan.h>

#include "gpu/layout.hpp"

namespace lancer::gpu {

VkDescriptorType descriptor_type(uint kind);
// VK_FORMAT_UNDEFINED for kinds that are not texel buffers.
VkFormat texel_format(uint kind);
VkBufferUsageFlags buffer_usage(uint kind);

}  // namespace lancer::gpu

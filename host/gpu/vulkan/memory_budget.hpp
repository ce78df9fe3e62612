#pragma once
// What a packed scene needs in GPU memory, and the check against what the device offers: each
// scene array within maxTexelBufferElements texels (the shader reads them as texel buffers), the
// output band within maxStorageBufferRange, and all of them together within the memory heap the
// buffers come from. A scene over any gets a UserError that names the need and the limit,
// instead of a driver failure.
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/layout.hpp"

namespace lancer::gpu {

// One buffer a render allocates: a descriptor of LANCER_RESOURCES at a size. Every pass states its
// buffers this way once; allocation and the memory budget read the same list.
struct BufferNeed {
    std::string what;     // "Bezier patch leaves"
    uint binding;         // BINDING_*: the resource, whose kind says which device limit applies
    std::uint64_t count;  // elements
    std::uint64_t bytes;
};

struct DeviceMemoryLimits {
    std::string device;                   // its name, for messages
    std::uint64_t max_texel_elements = 0;  // maxTexelBufferElements
    std::uint64_t max_storage_bytes = 0;   // maxStorageBufferRange
    std::uint64_t heap_bytes = 0;          // the heap of the memory type buffers are made from
};

// The need of `count` elements of a scene array, or of the resource at `binding`.
BufferNeed array_need(SceneArray array, std::uint64_t count);
BufferNeed resource_need(uint binding, std::uint64_t count);

// Whether one buffer is within its limit (texels for texel buffers, bytes for storage buffers).
bool fits(const BufferNeed& need, const DeviceMemoryLimits& limits);
// Throws UserError when one buffer exceeds its limit.
void check_buffer_need(const BufferNeed& need, const DeviceMemoryLimits& limits);
// Each buffer, then all of them together against heap_bytes.
void check_memory_budget(const std::vector<BufferNeed>& needs, const DeviceMemoryLimits& limits);

// "1.5 GiB", "128 MiB", "640 bytes".
std::string format_bytes(std::uint64_t bytes);

}  // namespace lancer::gpu

#pragma once
// What a scene needs in GPU memory, worked out from the scene model before anything is packed or
// allocated, and the check against what the device offers: no buffer larger than
// maxStorageBufferRange (the shader could not address the rest), and all of them together within
// the memory heap the buffers come from. A scene over either gets a UserError that names the need
// and the limit, instead of a driver failure or an allocation of gigabytes on the host.
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace lancer::gpu {

struct BufferNeed {
    std::string what;    // "Bezier patch leaves"
    std::uint64_t count;  // elements
    std::uint64_t bytes;
};

struct DeviceMemoryLimits {
    std::string device;                      // its name, for messages
    std::uint64_t max_buffer_bytes = 0;      // maxStorageBufferRange
    std::uint64_t heap_bytes = 0;            // the heap of the memory type buffers are made from
};

// Upper bounds of every scene buffer's size (the BVH at its largest, 2n - 1 nodes), plus the
// output band of `output_bytes`.
std::vector<BufferNeed> scene_buffer_needs(const Scene& scene, std::uint64_t output_bytes);

// Throws UserError when a buffer exceeds max_buffer_bytes or their sum exceeds heap_bytes.
void check_memory_budget(const std::vector<BufferNeed>& needs, const DeviceMemoryLimits& limits);

// "1.5 GiB", "128 MiB", "640 bytes".
std::string format_bytes(std::uint64_t bytes);

}  // namespace lancer::gpu

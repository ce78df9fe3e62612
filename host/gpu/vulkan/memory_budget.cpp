#include "gpu/vulkan/memory_budget.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace lancer::gpu {

BufferNeed array_need(SceneArray array, std::uint64_t count) { return resource_need(spec(array).binding, count); }

BufferNeed resource_need(uint binding, std::uint64_t count) {
    const ResourceSpec& s = resource(binding);
    return {s.what, binding, count, count * s.element_bytes};
}

bool fits(const BufferNeed& n, const DeviceMemoryLimits& limits) {
    const std::size_t texel = texel_bytes(resource(n.binding).kind);
    return texel ? n.bytes / texel <= limits.max_texel_elements : n.bytes <= limits.max_storage_bytes;
}

std::string format_bytes(std::uint64_t bytes) {
    constexpr double kMiB = 1024.0 * 1024.0, kGiB = kMiB * 1024.0;
    if (bytes >= std::uint64_t(kGiB)) return fmt::format("{:.1f} GiB", bytes / kGiB);
    if (bytes >= std::uint64_t(kMiB)) return fmt::format("{:.0f} MiB", bytes / kMiB);
    return fmt::format("{} bytes", bytes);
}

void check_buffer_need(const BufferNeed& n, const DeviceMemoryLimits& limits) {
    if (fits(n, limits)) return;
    const std::size_t texel = texel_bytes(resource(n.binding).kind);
    const std::string limit = texel ? fmt::format("{} ({} texels of {} bytes, maxTexelBufferElements)",
                                                  format_bytes(limits.max_texel_elements * texel), limits.max_texel_elements, texel)
                                    : fmt::format("{} (maxStorageBufferRange)", format_bytes(limits.max_storage_bytes));
    throw UserError(fmt::format(
        "the scene needs {} of GPU memory for its {} ({} of them), more than {} allows in one buffer, {}; use fewer "
        "or simpler objects (a lower subdivision for Bezier patches), or render with --backend cpu",
        format_bytes(n.bytes), n.what, n.count, limits.device, limit));
}

void check_memory_budget(const std::vector<BufferNeed>& needs, const DeviceMemoryLimits& limits) {
    std::uint64_t total = 0;
    for (const BufferNeed& n : needs) {
        check_buffer_need(n, limits);
        total += n.bytes;
    }
    if (total > limits.heap_bytes)
        throw UserError(fmt::format("the scene needs {} of GPU memory in all, more than {} has ({} in its memory heap); "
                                    "use fewer or simpler objects, or render with --backend cpu",
                                    format_bytes(total), limits.device, format_bytes(limits.heap_bytes)));
}

}  // namespace lancer::gpu

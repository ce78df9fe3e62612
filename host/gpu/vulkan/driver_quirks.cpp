#include "gpu/vulkan/driver_quirks.hpp"

#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "core/process_limits.hpp"
#include "gpu/vulkan/memory_budget.hpp"

namespace lancer::gpu {
namespace {

bool is_lavapipe(const DeviceInfo& device) { return device.driver_id == VK_DRIVER_ID_MESA_LLVMPIPE; }

constexpr std::uint64_t kPage = 4096;
// What the driver allocates in the file besides lancer's buffers: three pages measured on
// Mesa 25.0 (seed and cornell: the file ends 16 KiB past the sum of lancer's allocations).
constexpr std::uint64_t kDriverAllowance = 1 << 20;

}  // namespace

std::optional<int> mesa_version(const DeviceInfo& device) {
    const std::string::size_type at = device.driver.find("Mesa ");
    if (at == std::string::npos) return std::nullopt;
    int major = 0, minor = 0;
    if (std::sscanf(device.driver.c_str() + at + 5, "%d.%d", &major, &minor) != 2) return std::nullopt;
    return major * 100 + minor;
}

bool limits_loop_iterations(const DeviceInfo& device) {
    if (!is_lavapipe(device)) return false;
    const std::optional<int> version = mesa_version(device);
    return !version || *version < 2500;
}

bool hands_each_thread_one_run(const DeviceInfo& device) { return is_lavapipe(device); }

bool keeps_device_memory_in_a_file(const DeviceInfo& device) {
    if (!is_lavapipe(device)) return false;
    const std::optional<int> version = mesa_version(device);
    return !version || *version >= 2300;
}

void reserve_file_backed_memory(std::uint64_t& allocated, std::uint64_t bytes, std::uint64_t file_size_limit) {
    const std::uint64_t pages = (bytes + kPage - 1) / kPage * kPage;
    const std::uint64_t need = kPage + kDriverAllowance + allocated + pages;
    if (file_size_limit != kUnlimited && need > file_size_limit)
        throw UserError("lavapipe keeps the GPU's memory in a file, and the file size limit (ulimit -f) of " +
                        format_bytes(file_size_limit) + " is too small for it: this render needs up to " +
                        format_bytes(need) + "; raise the limit (ulimit -f unlimited) or render with --backend cpu");
    allocated += pages;
}

}  // namespace lancer::gpu

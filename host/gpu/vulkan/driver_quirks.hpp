#pragma once
// What lancer must know about particular Vulkan drivers, in one place: each rule names the
// driver versions it was measured on (docs/performance.md, "Mesa 25"). Where a version between
// two measured ones is unknown, the rule takes the safe side.
#include <cstdint>
#include <optional>

#include "gpu/vulkan/context.hpp"

namespace lancer::gpu {

// Mesa's version from the driver's info string ("Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)"): major
// times 100 plus minor (2500), or nothing for a driver that is not Mesa. (lavapipe's
// driverVersion field says 0.0.1 whatever the release.)
std::optional<int> mesa_version(const DeviceInfo& device);

// lavapipe up to Mesa 22.3 ends all loops of an invocation after 65535 iterations in total
// (gallivm's loop limiter) and the answers are silently wrong; Mesa 25.0 has no such limit.
// Where true, the tracer probes for it and renders cut-short bands again (trace.comp).
bool limits_loop_iterations(const DeviceInfo& device);

// lavapipe (Mesa 22.3 and 25.0: llvmpipe's lp_cs_tpool) splits a dispatch's workgroups into one
// run of consecutive indices per thread, fixed before any runs, so the thread whose run holds
// the costly part of a picture finishes last while the others wait (the teapot at 1280x720 kept
// 2 cores 83% busy, 94% with the runs spread). Where true, the tracer spreads each run over the
// band (tile_order.hpp).
bool hands_each_thread_one_run(const DeviceInfo& device);

// lavapipe from Mesa 25.0 keeps all device memory in one anonymous file that only grows
// (llvmpipe_allocate_memory: ftruncate without a check, then a mapping of it), so a file size
// limit (RLIMIT_FSIZE, `ulimit -f`) below its size kills the process with SIGBUS on first use.
// Mesa 22.3 allocates with malloc.
bool keeps_device_memory_in_a_file(const DeviceInfo& device);

// The file's size can reach at most one page plus every allocation ever made on the device, each
// rounded to a page (first fit from the lowest address: the high-water mark grows by at most the
// allocation's size). Throws UserError, naming the limit and what to do, when `bytes` more would
// not fit under the file size limit; `allocated` is that running sum, which it updates.
void reserve_file_backed_memory(std::uint64_t& allocated, std::uint64_t bytes, std::uint64_t file_size_limit);

}  // namespace lancer::gpu

#pragma once
// The memory a process may still take, as the system will enforce it: the address-space limit
// (RLIMIT_AS: `ulimit -v`, `prlimit --as`, what batch schedulers set) and the memory limit of its
// cgroup (memory.max, cgroup v2). Past either, a library that does not check its allocations (a
// Vulkan driver, LLVM) crashes or the kernel kills the process; lancer checks its estimated need
// against what is left first, and refuses with a message instead.
#include <cstdint>
#include <string>

namespace lancer {

constexpr std::uint64_t kUnlimited = UINT64_MAX;

struct MemoryHeadroom {
    std::uint64_t address_space_limit = kUnlimited;  // RLIMIT_AS (soft)
    std::uint64_t address_space_used = 0;             // VmSize
    std::uint64_t cgroup_limit = kUnlimited;         // memory.max of this process's cgroup
    std::uint64_t cgroup_used = 0;                    // memory.current of that cgroup
};

MemoryHeadroom memory_headroom();

// The largest file this process may write (RLIMIT_FSIZE, soft: `ulimit -f`), or kUnlimited.
std::uint64_t file_size_limit();

// Throws UserError when `address_space` more bytes of address space, or `resident` more bytes of
// memory, do not fit under the limits: "WHAT needs about N MiB more address space, but the limit
// (ulimit -v) is L MiB and U MiB of it are in use: ADVICE".
void check_memory_headroom(std::uint64_t address_space, std::uint64_t resident, const std::string& what,
                           const std::string& advice);

// Whether an address-space limit is set: glibc's malloc then keeps one arena (each further arena
// reserves 64 MiB of address space, one per thread that allocates), which lavapipe's threads
// would otherwise multiply (docs/robustness.md). Called once, at the start of main().
void adapt_to_address_space_limit();

}  // namespace lancer

#include "core/process_limits.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <malloc.h>
#include <sys/resource.h>

#include <fmt/format.h>

#include "core/error.hpp"

namespace lancer {
namespace {

// "VmSize:   123456 kB" from /proc/self/status, in bytes.
std::uint64_t status_bytes(const std::string& key) {
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(key + ":", 0) != 0) continue;
        std::istringstream fields(line.substr(key.size() + 1));
        std::uint64_t kib = 0;
        fields >> kib;
        return kib * 1024;
    }
    return 0;
}

// A number from a cgroup file, kUnlimited for "max", for cgroup v1's "no limit" (a page-rounded
// LONG_MAX) or when there is none.
std::uint64_t cgroup_value(const std::string& path) {
    std::ifstream in(path);
    std::string text;
    if (!(in >> text) || text == "max") return kUnlimited;
    try {
        std::uint64_t value = std::stoull(text);
        return value >= (std::uint64_t{1} << 62) ? kUnlimited : value;
    } catch (...) {
        return kUnlimited;
    }
}

// Walks from the cgroup `dir` up to the root under `mount` (the limit of any ancestor applies),
// keeping the one with the least room left.
void tightest_cgroup(const std::string& mount, std::string dir, const char* max_file, const char* current_file,
                     MemoryHeadroom& h) {
    for (;;) {
        const std::uint64_t max = cgroup_value(mount + dir + "/" + max_file);
        if (max != kUnlimited) {
            const std::uint64_t used = std::min(max, cgroup_value(mount + dir + "/" + current_file));
            if (h.cgroup_limit == kUnlimited || max - used < h.cgroup_limit - h.cgroup_used) {
                h.cgroup_limit = max;
                h.cgroup_used = used;
            }
        }
        if (dir.empty() || dir == "/") return;
        dir = dir.substr(0, dir.find_last_of('/'));
    }
}

std::string mib(std::uint64_t bytes) { return fmt::format("{} MiB", (bytes + (1 << 20) - 1) >> 20); }

}  // namespace

MemoryHeadroom memory_headroom() {
    MemoryHeadroom h;
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) h.address_space_limit = limit.rlim_cur;
    h.address_space_used = status_bytes("VmSize");
    // "0::/path" (cgroup v2) or "N:memory:/path" (v1) in /proc/self/cgroup.
    std::ifstream in("/proc/self/cgroup");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("0::", 0) == 0)
            tightest_cgroup("/sys/fs/cgroup", line.substr(3), "memory.max", "memory.current", h);
        else if (auto at = line.find(":memory:"); at != std::string::npos)
            tightest_cgroup("/sys/fs/cgroup/memory", line.substr(at + 8), "memory.limit_in_bytes", "memory.usage_in_bytes", h);
    }
    return h;
}

void check_memory_headroom(std::uint64_t address_space, std::uint64_t resident, const std::string& what,
                           const std::string& advice) {
    const MemoryHeadroom h = memory_headroom();
    if (h.address_space_limit != kUnlimited && h.address_space_used + address_space > h.address_space_limit)
        throw UserError(fmt::format("{} needs about {} more address space, but the address-space limit (ulimit -v) is "
                                    "{} and {} of it are in use: raise it to at least {}, {}",
                                    what, mib(address_space), mib(h.address_space_limit), mib(h.address_space_used),
                                    mib(h.address_space_used + address_space), advice));
    if (h.cgroup_limit != kUnlimited && h.cgroup_used + resident > h.cgroup_limit)
        throw UserError(fmt::format("{} needs about {} more memory, but its cgroup's limit (memory.max) is {} and {} of "
                                    "it are in use: {}",
                                    what, mib(resident), mib(h.cgroup_limit), mib(h.cgroup_used), advice));
}

std::uint64_t file_size_limit() {
    struct rlimit limit {};
    if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) return limit.rlim_cur;
    return kUnlimited;
}

void adapt_to_address_space_limit() {
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) ::mallopt(M_ARENA_MAX, 1);
}

}  // namespace lancer

#include "core/page_release.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

namespace lancer {

const void* release_pages(const void* begin, const void* end) {
    static const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    const auto b = reinterpret_cast<std::uintptr_t>(begin), e = reinterpret_cast<std::uintptr_t>(end);
    const std::uintptr_t first = (b + page - 1) & ~(page - 1), last = e & ~(page - 1);
    if (first >= last) return begin;
    ::madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
    return reinterpret_cast<const void*>(last);
}

const void* release_pages_back(const void* begin, const void* end) {
    static const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    const auto b = reinterpret_cast<std::uintptr_t>(begin), e = reinterpret_cast<std::uintptr_t>(end);
    const std::uintptr_t first = (b + page - 1) & ~(page - 1), last = e & ~(page - 1);
    if (first >= last) return end;
    ::madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
    return reinterpret_cast<const void*>(first);
}

}  // namespace lancer

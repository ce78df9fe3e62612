#include "core/page_release.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

namespace lancer {
namespace {

struct Pages {
    const void* first;  // begin rounded up to its page
    const void* last;   // end rounded down to its page
    bool released;      // whether any whole page lay between them (and was given back)
};

Pages release_whole_pages(const void* begin, const void* end) {
    static const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    const auto b = reinterpret_cast<std::uintptr_t>(begin), e = reinterpret_cast<std::uintptr_t>(end);
    const std::uintptr_t first = (b + page - 1) & ~(page - 1), last = e & ~(page - 1);
    if (first >= last) return {begin, end, false};
    ::madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
    return {reinterpret_cast<const void*>(first), reinterpret_cast<const void*>(last), true};
}

}  // namespace

const void* release_pages(const void* begin, const void* end) {
    const Pages p = release_whole_pages(begin, end);
    return p.released ? p.last : begin;
}

const void* release_pages_back(const void* begin, const void* end) {
    const Pages p = release_whole_pages(begin, end);
    return p.released ? p.first : end;
}

}  // namespace lancer

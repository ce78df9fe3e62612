#pragma once
// Copying a big array into another piece by piece, giving the source's pages back to the kernel
// behind the copy: the two never coexist whole, so the peak holds one array, not two.
#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace lancer {

// Gives the kernel back the whole pages within [begin, end), which their owner will not read
// again (madvise MADV_DONTNEED: touched again, they would read as zeros). Returns where the next
// call over the rest of the array should begin: end rounded down to its page.
const void* release_pages(const void* begin, const void* end);

// For an array given up from its end: gives back the whole pages within [begin, end) and returns
// where the next call over the rest should end: begin rounded up to its page (end where none was
// whole).
const void* release_pages_back(const void* begin, const void* end);

// Calls visit(x) for each element of `from` in order, releasing its pages behind the visits,
// then empties it. Whatever `visit` fills should have its room reserved, or its growth holds
// two copies again.
template <class T, class Visit>
void drain(std::vector<T>& from, Visit visit) {
    static_assert(std::is_trivially_destructible_v<T>, "released elements are never destroyed");
    constexpr std::size_t kStep = std::max<std::size_t>(1, (std::size_t(2) << 20) / sizeof(T));
    const void* released = from.data();
    for (std::size_t i = 0; i < from.size(); i += kStep) {
        const std::size_t end = std::min(from.size(), i + kStep);
        for (std::size_t k = i; k < end; ++k) visit(static_cast<const T&>(from[k]));
        released = release_pages(released, from.data() + end);
    }
    std::vector<T>().swap(from);
}

// Calls visit(x) for each element of `from`, the last first, destroying each after its visit and
// giving its pages back behind it, then frees the array: for elements that must be destroyed
// (only the vector's spare room is released, which it never reads).
template <class T, class Visit>
void drain_from_back(std::vector<T>& from, Visit visit) {
    constexpr std::size_t kStep = std::max<std::size_t>(1, (std::size_t(2) << 20) / sizeof(T));
    const void* kept_end = from.data() + from.size();
    while (!from.empty()) {
        const std::size_t stop = from.size() > kStep ? from.size() - kStep : 0;
        while (from.size() > stop) {
            visit(from.back());
            from.pop_back();
        }
        kept_end = release_pages_back(from.data() + from.size(), kept_end);
    }
    std::vector<T>().swap(from);
}

}  // namespace lancer

#pragma once
// Transparent huge pages for lancer's largest arrays. A big scene fills hundreds of MiB (a million
// spheres' boxes and trees, the GPU's copies of them), and touching each 4 KiB page the first time
// costs a page fault: a quarter of such a render's time on a VM (docs/performance.md, "Sphere
// sets"). Where the kernel gives 2 MiB pages on request (transparent_hugepage "madvise"), asking
// for them before an array is filled takes one fault per 2 MiB instead of 512. Small arrays
// are left alone: huge pages would only cost them memory.
#include <cstddef>
#include <vector>

namespace lancer {

// Asks for huge pages over the 2 MiB-aligned part of [data, data + bytes) (madvise; nothing
// where the kernel cannot, or the range holds no whole huge page).
void advise_huge_pages(void* data, std::size_t bytes);

// v.reserve(n), with huge pages for its storage where it is large (at least kHugeArrayBytes):
// call before filling v, while its pages are untouched.
inline constexpr std::size_t kHugeArrayBytes = std::size_t(8) << 20;
template <class T>
void reserve_huge(std::vector<T>& v, std::size_t n) {
    const bool fresh = v.capacity() < n;
    v.reserve(n);
    if (fresh && n * sizeof(T) >= kHugeArrayBytes) advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace lancer

#pragma once
// A cap on the memory stb_image may allocate while it decodes one image, on this thread. stb
// sizes its buffers from the file's content: a zlib stream that inflates to far more than the
// header's size (a decompression bomb) grows its output buffer until memory runs out. Under a
// budget, the allocation that would cross the cap fails, and stb gives up with "outofmem".
#include <cstddef>

namespace lancer {

class DecodeBudget {
public:
    explicit DecodeBudget(std::size_t bytes);
    ~DecodeBudget();
    DecodeBudget(const DecodeBudget&) = delete;
    DecodeBudget& operator=(const DecodeBudget&) = delete;

    bool exceeded() const;  // an allocation was refused
};

// stb_image's allocator (stb_image.cpp): malloc, realloc and free that count against the
// budget of the calling thread, if it has one.
void* budget_malloc(std::size_t bytes);
void* budget_realloc(void* block, std::size_t bytes);
void budget_free(void* block);

}  // namespace lancer

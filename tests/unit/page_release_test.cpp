// drain (core/page_release.hpp): every element visited once, in order, across the steps whose
// pages it gives back; the array emptied after. drain_from_back: the last first, each destroyed
// once after its visit, the pages behind given back.
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <memory>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "core/page_release.hpp"

namespace lancer {
namespace {

TEST(Drain, VisitsEveryElementInOrderAndEmptiesTheArray) {
    for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(1000), std::size_t(3) << 20}) {
        std::vector<std::uint32_t> from(n);
        std::iota(from.begin(), from.end(), 0u);
        std::vector<std::uint32_t> to;
        to.reserve(n);
        drain(from, [&](std::uint32_t x) { to.push_back(x); });
        EXPECT_TRUE(from.empty());
        EXPECT_EQ(from.capacity(), 0u);
        ASSERT_EQ(to.size(), n);
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(to[i], i);
    }
}

struct Counted {
    std::uint64_t value;
    std::shared_ptr<int> token;  // its use count: the elements alive, and the test's own
};

bool page_resident(const void* address) {
    const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    unsigned char in_core = 0;
    void* start = reinterpret_cast<void*>(reinterpret_cast<std::uintptr_t>(address) & ~(page - 1));
    EXPECT_EQ(::mincore(start, page, &in_core), 0);
    return (in_core & 1) != 0;
}

TEST(Drain, FromTheBackVisitsEachElementThenDestroysItAndGivesItsPagesBack) {
    const auto token = std::make_shared<int>(0);
    constexpr std::size_t kStep = (std::size_t(2) << 20) / sizeof(Counted);
    for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(1000), 5 * kStep + 7}) {
        std::vector<Counted> from;
        from.reserve(n);
        for (std::size_t i = 0; i < n; ++i) from.push_back({i, token});
        const Counted* data = from.data();
        std::size_t expected = n, checked_pages = 0;
        drain_from_back(from, [&](const Counted& c) {
            ASSERT_EQ(c.value + 1, expected--);
            ASSERT_EQ(std::size_t(token.use_count()), c.value + 2) << "the ones after it destroyed, none before";
            if (c.value + 3 * kStep < n && c.value % 4096 == 0) {
                EXPECT_FALSE(page_resident(data + c.value + 3 * kStep)) << "element " << c.value << ": two steps behind";
                ++checked_pages;
            }
        });
        EXPECT_EQ(expected, 0u);
        EXPECT_EQ(token.use_count(), 1);
        EXPECT_TRUE(from.empty());
        EXPECT_EQ(from.capacity(), 0u);
        if (n > 4 * kStep) {
            EXPECT_GT(checked_pages, 0u);
        }
    }
}

}  // namespace
}  // namespace lancer

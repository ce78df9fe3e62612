// drain (core/page_release.hpp): every element visited once, in order, across the steps whose
// pages it gives back; the array emptied after.
#include <cstdint>
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

}  // namespace
}  // namespace lancer

// The order in which a dispatch's workgroups take the band's tiles (gpu/tile_order.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "gpu/tile_order.hpp"

namespace lancer {
namespace {

// The tiles, in rows of `columns`, that lavapipe's thread `t` of `threads` renders: one run of
// consecutive workgroups each (llvmpipe's lp_cs_tpool: groups / threads, the remainder one by one).
std::vector<std::uint32_t> run_of_thread(std::uint32_t groups, std::uint32_t threads, std::uint32_t t) {
    const std::uint32_t per = groups / threads, stride = gpu::spread_group_stride(groups);
    std::vector<std::uint32_t> tiles;
    for (std::uint32_t g = t * per; g < (t + 1) * per; ++g) tiles.push_back(std::uint32_t(std::uint64_t(g) * stride % groups));
    return tiles;
}

TEST(TileOrder, EveryTileIsTakenOnce) {
    for (std::uint32_t groups = 1; groups <= 4000; ++groups) {
        const std::uint32_t stride = gpu::spread_group_stride(groups);
        ASSERT_EQ(std::gcd(stride, groups), 1u) << groups;
        ASSERT_LE(std::uint64_t(groups - 1) * stride, 0xffffffffull) << groups;  // the shader's product
        std::vector<bool> taken(groups, false);
        for (std::uint32_t g = 0; g < groups; ++g) taken[std::uint64_t(g) * stride % groups] = true;
        ASSERT_EQ(std::count(taken.begin(), taken.end(), true), groups) << groups;
    }
    for (std::uint32_t groups = 65000; groups <= 65535; ++groups)  // the largest spread: the product still fits
        ASSERT_LE(std::uint64_t(groups - 1) * gpu::spread_group_stride(groups), 0xffffffffull) << groups;
    EXPECT_EQ(gpu::spread_group_stride(65536), 1u);  // past what the shader's product holds: in order
}

// Each thread's run covers the band evenly, whatever the number of threads: the rows of its
// tiles average to the band's middle, and each quarter of the band holds its share of them.
// (In order, thread 0 of 2 would take the top half alone: 0.25 and 0.47 off.)
TEST(TileOrder, EachThreadsRunCoversTheBandEvenly) {
    struct Band {
        std::uint32_t columns, rows;
    };
    // 1280 x 720 at 9 rays a pixel (bands of 102 rows), a 4K band, a narrow image.
    for (const Band band : {Band{160, 13}, Band{480, 9}, Band{40, 23}}) {
        const std::uint32_t groups = band.columns * band.rows;
        auto quarter = [&](std::uint32_t row) { return std::min(3, int((row + 0.5) / band.rows * 4.0)); };
        std::vector<double> band_quarters(4, 0.0);
        for (std::uint32_t row = 0; row < band.rows; ++row) band_quarters[quarter(row)] += 1.0 / band.rows;
        for (std::uint32_t threads : {2u, 3u, 4u, 8u, 16u}) {
            for (std::uint32_t t = 0; t < threads; ++t) {
                const std::vector<std::uint32_t> tiles = run_of_thread(groups, threads, t);
                double mean_row = 0.0;
                std::vector<double> quarters(4, 0.0);
                for (std::uint32_t tile : tiles) {
                    const std::uint32_t row = tile / band.columns;
                    mean_row += (row + 0.5) / band.rows / tiles.size();
                    quarters[quarter(row)] += 1.0 / tiles.size();
                }
                SCOPED_TRACE(testing::Message() << band.columns << " x " << band.rows << ", thread " << t << " of " << threads);
                EXPECT_NEAR(mean_row, 0.5, 0.03);
                for (int q = 0; q < 4; ++q) EXPECT_NEAR(quarters[q], band_quarters[q], 0.05);
            }
        }
    }
}

}  // namespace
}  // namespace lancer

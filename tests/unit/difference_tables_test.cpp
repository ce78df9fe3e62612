// The tables from which the GPU decides adaptive anti-aliasing's colour differences
// (image/difference_tables.hpp) must decide exactly as the host's functions do: every float's
// sRGB code is the number of level starts it reaches, and every triple of code differences
// exceeds the threshold exactly when its blue difference reaches the table's floor.
#include <bit>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "image/adaptive.hpp"
#include "image/difference_tables.hpp"
#include "image/image.hpp"

namespace lancer {
namespace {

// The code the tables give a float, found as shaders/refine_select.comp finds it: the highest
// level whose start it reaches, by bisection.
int code_from_levels(float f) {
    const auto& starts = srgb8_level_starts();
    int code = 0;
    for (int half = 128; half > 0; half /= 2)
        if (f >= starts[code + half]) code += half;
    return code;
}

TEST(DifferenceTables, LevelStartsAreWhereEachCodeBegins) {
    const auto& starts = srgb8_level_starts();
    for (int k = 1; k < 256; ++k) {
        ASSERT_EQ(encode_srgb8_by_formula(starts[k]), k) << k;
        ASSERT_EQ(encode_srgb8_by_formula(std::nextafter(starts[k], 0.0f)), k - 1) << k;
        ASSERT_LT(starts[k - 1], starts[k]) << k;
    }
}

// encode_srgb8_by_formula is non-decreasing over all of [0, 1] (checked float by float once, which takes
// a minute); here every float within 2^12 of each level start, where powf's rounding could
// break it, gets the code the tables give it.
TEST(DifferenceTables, CodesFromLevelStartsAreEncodeSrgb8NearEveryStart) {
    const auto& starts = srgb8_level_starts();
    for (int k = 1; k < 256; ++k) {
        const auto at = std::bit_cast<std::uint32_t>(starts[k]);
        for (std::uint32_t u = at - 4096; u <= at + 4096; ++u) {
            const float f = std::bit_cast<float>(u);
            ASSERT_EQ(code_from_levels(f), encode_srgb8_by_formula(f)) << "level " << k << ", float " << f;
        }
    }
    for (float f : {-1.0f, -0.0f, 0.0f, 2.0f, std::numeric_limits<float>::infinity(),
                    -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                    std::numeric_limits<float>::denorm_min()})
        EXPECT_EQ(code_from_levels(f), encode_srgb8_by_formula(f)) << f;
}

// Every triple of code differences, at thresholds where the sum's rounding depends on how the
// differences split among the channels (0.6: 153/255, 1.0: 255/255), at POV-Ray's default and
// at the ends.
TEST(DifferenceTables, BlueFloorsDecideEveryTripleAsCodeDifferenceDoes) {
    for (double threshold : {0.6, 1.0, 0.3, 0.0, 3.0, -1.0}) {
        const std::vector<std::uint32_t> floors = blue_difference_floors(threshold);
        ASSERT_EQ(floors.size(), 256u * 256u);
        int wrong = 0, split_decides = 0;
        for (int dr = 0; dr < 256; ++dr)
            for (int dg = 0; dg < 256; ++dg)
                for (int db = 0; db < 256; ++db) {
                    const bool differs = code_difference(dr, dg, db) > threshold;
                    if ((std::uint32_t(db) >= floors[std::size_t(dr) * 256 + dg]) != differs && wrong++ == 0)
                        ADD_FAILURE() << threshold << ": first wrong at " << dr << " " << dg << " " << db;
                    split_decides += dr + dg + db == 153 && differs;
                }
        EXPECT_EQ(wrong, 0) << threshold;
        // Some of the splits of 153 exceed 0.6 and some do not: a rule on the sum of the codes alone fails.
        if (threshold == 0.6) {
            EXPECT_GT(split_decides, 0);
        }
    }
}

// color_difference is code_difference of the codes' distances.
TEST(DifferenceTables, ColorDifferenceIsCodeDifferenceOfTheCodes) {
    const glm::vec4 a(0.2f, 0.7f, 0.01f, 1.0f), b(0.9f, 0.1f, 0.5f, 3.0f);
    const int dr = std::abs(encode_srgb8(a.r) - encode_srgb8(b.r)), dg = std::abs(encode_srgb8(a.g) - encode_srgb8(b.g)),
              db = std::abs(encode_srgb8(a.b) - encode_srgb8(b.b));
    EXPECT_EQ(color_difference(a, b), code_difference(dr, dg, db));
    EXPECT_EQ(color_difference(a, b), color_difference(b, a));
}

}  // namespace
}  // namespace lancer

#include <bit>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "image/diff.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

TEST(Srgb, EncodesTheStandardCurve) {
    EXPECT_EQ(encode_srgb8(0.0f), 0);
    EXPECT_EQ(encode_srgb8(1.0f), 255);
    EXPECT_EQ(encode_srgb8(0.5f), 188);         // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354
    EXPECT_EQ(encode_srgb8(0.0031308f), 10);    // end of the linear segment: 12.92 * x = 0.04045
    EXPECT_EQ(encode_srgb8(0.2158605f), 128);   // sRGB 0.5019 = 128/255
}

TEST(Srgb, ClampsOutOfRangeAndNaN) {
    EXPECT_EQ(encode_srgb8(-1.0f), 0);
    EXPECT_EQ(encode_srgb8(7.0f), 255);
    EXPECT_EQ(encode_srgb8(std::nanf("")), 0);
}

// Pictures are encoded from tables (image/srgb.cpp); every code must be the formula's. Checked
// where the tables could go wrong: at and around every level start, at the start of every run
// of floats that shares a table entry, at the ends and at random.
TEST(Srgb, TablesGiveTheFormulasCodes) {
    for (float start : srgb8_level_starts()) {
        const auto at = std::bit_cast<std::uint32_t>(start);
        for (std::uint32_t u = at < 64 ? 0 : at - 64; u <= at + 64; ++u)
            ASSERT_EQ(encode_srgb8(std::bit_cast<float>(u)), encode_srgb8_by_formula(std::bit_cast<float>(u))) << u;
    }
    const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
    for (std::uint32_t run = 0; run <= one; run += 1u << 16)
        for (std::uint32_t u : {run, run + 1, run - 1, run + 0xffffu}) {
            const float f = std::bit_cast<float>(u);
            ASSERT_EQ(encode_srgb8(f), encode_srgb8_by_formula(f)) << u;
        }
    std::mt19937 random(7);
    std::uniform_int_distribution<std::uint32_t> pattern(0, one + 4096);
    for (int i = 0; i < 1'000'000; ++i) {
        const float f = std::bit_cast<float>(pattern(random));
        ASSERT_EQ(encode_srgb8(f), encode_srgb8_by_formula(f)) << f;
    }
    for (float f : {-1.0f, -0.0f, 0.0f, 1.0f, 7.0f, std::numeric_limits<float>::infinity(),
                    -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                    std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max()})
        EXPECT_EQ(encode_srgb8(f), encode_srgb8_by_formula(f)) << f;
}

TEST(Srgb, DecodeInvertsEncode) {
    for (int i = 0; i < 256; ++i) EXPECT_EQ(encode_srgb8(decode_srgb8(static_cast<std::uint8_t>(i))), i);
}

Rgb8Image flat(int w, int h, std::uint8_t v) { return {w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3, v)}; }

TEST(ImageDiff, IdenticalImagesHaveInfinitePsnr) {
    ImageDiff d = compare_images(flat(4, 4, 9), flat(4, 4, 9), 4);
    EXPECT_TRUE(std::isinf(d.psnr_db));
    EXPECT_EQ(d.max_abs, 0);
    EXPECT_EQ(d.fraction_over, 0.0);
}

TEST(ImageDiff, CountsPixelsOverTheThreshold) {
    Rgb8Image a = flat(10, 10, 100), b = a;
    b.bytes[0] = 110;   // pixel 0, off by 10
    b.bytes[5] = 103;   // pixel 1, off by 3: under the threshold
    ImageDiff d = compare_images(a, b, 4);
    EXPECT_EQ(d.max_abs, 10);
    EXPECT_DOUBLE_EQ(d.fraction_over, 0.01);
    EXPECT_NEAR(d.psnr_db, 10 * std::log10(255.0 * 255.0 / ((100.0 + 9.0) / 300.0)), 1e-9);
}

TEST(ImageDiff, SizeMismatchIsAnError) { EXPECT_THROW(compare_images(flat(2, 2, 0), flat(3, 2, 0), 4), UserError); }

TEST(Png, RoundTripsAndReplacesAtomically) {
    std::string path = test::output_dir() + "/roundtrip.png";
    Rgb8Image img = flat(3, 2, 0);
    for (std::size_t i = 0; i < img.bytes.size(); ++i) img.bytes[i] = static_cast<std::uint8_t>(i * 13);
    write_png(path, img);
    Rgb8Image back = read_png(path);
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(back.height, 2);
    EXPECT_EQ(back.bytes, img.bytes);
    // No temporary files are left beside it.
    for (const auto& entry : std::filesystem::directory_iterator(test::output_dir()))
        EXPECT_NE(entry.path().filename().string().rfind(".roundtrip.png.", 0), 0u) << entry.path();
}

TEST(Png, UnwritableDestinationIsAUserError) {
    EXPECT_THROW(write_png("/nonexistent-dir/x.png", flat(1, 1, 0)), UserError);
    EXPECT_THROW(write_png(test::output_dir(), flat(1, 1, 0)), UserError);  // a directory
}

}  // namespace
}  // namespace lancer

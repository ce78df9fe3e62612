// Frame names, --frames ranges and the short frame lists of messages.
#include <gtest/gtest.h>

#include "app/frame_pattern.hpp"
#include "core/error.hpp"

namespace lancer {
namespace {

TEST(FramePattern, ExpandsPaddedAndPlainFields) {
    auto p = FramePattern::parse("frames/orbit_%04d.png");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->path(0), "frames/orbit_0000.png");
    EXPECT_EQ(p->path(119), "frames/orbit_0119.png");
    EXPECT_EQ(p->path(123456), "frames/orbit_123456.png");  // wider than the padding: printf's rule
    EXPECT_EQ(p->directory(), "frames");
    auto plain = FramePattern::parse("f%d.png");
    ASSERT_TRUE(plain);
    EXPECT_EQ(plain->path(7), "f7.png");
    EXPECT_EQ(plain->directory(), "");
    auto percent = FramePattern::parse("100%%_%02d.png");
    ASSERT_TRUE(percent);
    EXPECT_EQ(percent->path(3), "100%_03.png");
    EXPECT_EQ(percent->text(), "100%%_%02d.png");  // as ffmpeg reads it
}

TEST(FramePattern, NameWithoutAFieldIsNoPattern) {
    EXPECT_FALSE(FramePattern::parse("poster.png"));
    EXPECT_FALSE(FramePattern::parse("100%%.png"));
    EXPECT_FALSE(has_frame_field("poster.png"));
    EXPECT_TRUE(has_frame_field("o_%03d.png"));
    EXPECT_FALSE(has_frame_field("50%off.png"));  // a stray % in a still's name is just a character
}

TEST(FramePattern, RejectsWhatFfmpegWouldReadDifferently) {
    for (const char* bad : {"o_%s.png", "o_%5d.png", "o_%d_%d.png", "o_%00d.png", "o_%010d.png", "o_%", "dir%02d/o.png"})
        EXPECT_THROW(FramePattern::parse(bad), UserError) << bad;
}

TEST(FramePattern, PadWidthIsTheDigitsOfTheLastFrame) {
    EXPECT_EQ(frame_number_width(1), 1);
    EXPECT_EQ(frame_number_width(10), 1);   // 0-9
    EXPECT_EQ(frame_number_width(11), 2);   // 0-10
    EXPECT_EQ(frame_number_width(120), 3);  // 0-119
    EXPECT_EQ(frame_number_width(1000), 3);
    EXPECT_EQ(frame_number_width(1001), 4);
    EXPECT_EQ(default_frame_pattern("scenes/orbit.toml", 120), "orbit_%03d.png");
    EXPECT_EQ(default_frame_pattern("a%b.toml", 5), "a%%b_%d.png");
    EXPECT_EQ(FramePattern::parse(default_frame_pattern("a%b.toml", 5))->path(4), "a%b_4.png");
}

TEST(FrameRange, ParsesRangesAndSingleFrames) {
    FrameRange r = parse_frame_range("10-19", 120);
    EXPECT_EQ(r.first, 10);
    EXPECT_EQ(r.last, 19);
    EXPECT_FALSE(r.single());
    r = parse_frame_range("7", 120);
    EXPECT_EQ(r.first, 7);
    EXPECT_TRUE(r.single());
    r = parse_frame_range("0-119", 120);
    EXPECT_EQ(r.last, 119);
}

TEST(FrameRange, RejectsRangesOutsideTheAnimation) {
    for (const char* bad : {"0-120", "120", "5-2", "-3", "3-", "a-b", "1-2-3", "", " 4", "4.5"})
        EXPECT_THROW(parse_frame_range(bad, 120), UserError) << bad;
    try {
        parse_frame_range("0-200", 120);
    } catch (const UserError& e) {
        EXPECT_STREQ(e.what(), "--frames 0-200: the animation has 120 frames, 0-119");
    }
}

TEST(FrameList, ShortensRuns) {
    EXPECT_EQ(format_frame_list({}), "");
    EXPECT_EQ(format_frame_list({2}), "2");
    EXPECT_EQ(format_frame_list({0, 1, 3, 4, 5, 9}), "0-1, 3-5, 9");
}

}  // namespace
}  // namespace lancer

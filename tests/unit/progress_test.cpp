// The animation's live progress line: contents, estimate and fitting the terminal.
#include <gtest/gtest.h>

#include "cli/progress.hpp"

namespace lancer {
namespace {

TEST(Progress, ClockFormat) {
    EXPECT_EQ(format_clock(0), "0:00");
    EXPECT_EQ(format_clock(7.4), "0:07");
    EXPECT_EQ(format_clock(754), "12:34");
    EXPECT_EQ(format_clock(3723), "1:02:03");
    EXPECT_EQ(format_clock(-3), "0:00");
}

TEST(Progress, EstimateIsTheMeanFrameTimeTimesWhatIsLeft) {
    EXPECT_LT(estimate_remaining(0.1, 0, 0.0, 10), 0.0);  // nothing to go on yet
    EXPECT_DOUBLE_EQ(estimate_remaining(20.0, 2, 0.0, 10), 80.0);
    EXPECT_DOUBLE_EQ(estimate_remaining(25.0, 2, 0.5, 10), 75.0);  // 10 s per frame, 7.5 frames left
    EXPECT_DOUBLE_EQ(estimate_remaining(5.0, 0, 0.5, 4), 35.0);
    EXPECT_DOUBLE_EQ(estimate_remaining(40.0, 4, 0.0, 4), 0.0);
}

TEST(Progress, LiveLineShowsFramePercentElapsedAndEta) {
    FrameStatus s{3, 10, "frames/orbit_012.png", 0.45, 12.0, 65.0};
    EXPECT_EQ(format_frame_status(s, 200), "frame 3/10 frames/orbit_012.png   45%  0:12 elapsed, ETA 1:05");
    s.eta = -1;
    EXPECT_NE(format_frame_status(s, 200).find("ETA --:--"), std::string::npos);
}

// A line as wide as the terminal wraps and every rewrite then adds a line (POV-Ray issue #247):
// the path gives way first, the numbers stay.
TEST(Progress, LiveLineNeverReachesTheLastColumn) {
    FrameStatus s{118, 120, "/a/very/long/directory/name/for/frames/orbit_0117.png", 0.99, 3600.0, 30.0};
    for (int width : {200, 80, 60, 50, 40, 20, 5, 1}) {
        std::string line = format_frame_status(s, width);
        EXPECT_LE(static_cast<int>(line.size()), std::max(0, width - 1)) << width;
    }
    std::string at60 = format_frame_status(s, 70);
    EXPECT_NE(at60.find("ETA 0:30"), std::string::npos) << at60;
    EXPECT_NE(at60.find("orbit_0117.png"), std::string::npos) << at60;
    EXPECT_NE(at60.find("..."), std::string::npos) << at60;
}

TEST(Progress, APhaseShowsWhatAndItsWholeSeconds) {
    EXPECT_EQ(format_phase("reading big.toml", 12.7), "reading big.toml  12 s");
    EXPECT_EQ(format_phase("preparing x.png", 0.2), "preparing x.png  0 s");
}

}  // namespace
}  // namespace lancer

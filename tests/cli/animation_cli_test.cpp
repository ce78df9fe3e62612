// `lancer render` on animated scenes as users run it: frame files, resuming, subsets, the
// video, the progress display, and the exit code 2 cases.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "image/image.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

const std::string kScene = test::small_animation();

// A fresh, empty directory under build/test-output for one test.
std::string anim_dir(const std::string& name) { return test::fresh_dir("anim-" + name); }

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// The lines "PATH: frame K (i/n), S s" that a non-terminal run prints per rendered frame.
std::vector<std::string> rendered_frame_lines(const std::string& err) {
    static const std::regex per_frame(R"(^.*: frame \d+ \(\d+/\d+\), [0-9.]+ s$)");
    std::vector<std::string> out;
    for (const std::string& line : lines_of(err))
        if (std::regex_match(line, per_frame)) out.push_back(line);
    return out;
}

struct FileId {
    ino_t inode;
    timespec mtime;
};
FileId file_id(const std::string& path) {
    struct stat st {};
    EXPECT_EQ(::stat(path.c_str(), &st), 0) << path;
    return {st.st_ino, st.st_mtim};
}
bool same_file(const FileId& a, const FileId& b) {
    return a.inode == b.inode && a.mtime.tv_sec == b.mtime.tv_sec && a.mtime.tv_nsec == b.mtime.tv_nsec;
}

std::size_t files_in(const std::string& dir) {
    if (!fs::exists(dir)) return 0;
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(AnimationCli, RendersEveryFrameWithOnePlainLinePerFrameAndASummary) {
    std::string dir = anim_dir("all");
    auto r = test::run_lancer("render " + kScene + " -o " + dir + "/f_%02d.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (int k = 0; k < 6; ++k) {
        std::string path = dir + "/f_0" + std::to_string(k) + ".png";
        ASSERT_TRUE(test::file_exists(path)) << path;
        EXPECT_EQ(read_png(path).width, 48);
    }
    EXPECT_FALSE(test::file_exists(dir + "/f_06.png")) << "a cyclic animation leaves frame N (= frame 0) out";
    EXPECT_EQ(files_in(dir), 6u) << "no temporary files are left behind";
    EXPECT_EQ(rendered_frame_lines(r.err).size(), 6u) << r.err;
    EXPECT_NE(r.err.find(dir + "/f_00.png: frame 0 (1/6)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("rendered 6 frame(s): 0-5"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("start-up"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\r'), std::string::npos) << "no carriage returns when stderr is not a terminal";
    // Frames differ from each other: the animation moves.
    EXPECT_NE(slurp(dir + "/f_00.png"), slurp(dir + "/f_01.png"));
}

// The issue's resume test: render 0-4, delete frame 2, render again. Only frame 2 is rendered
// (the log says so; the other files keep their inode and mtime), and all five are byte for
// byte what a clean run makes.
TEST(AnimationCli, ResumeRendersOnlyTheMissingFrame) {
    std::string dir = anim_dir("resume"), clean = anim_dir("resume-clean");
    ASSERT_EQ(test::run_lancer("render " + kScene + " --frames 0-4 -o " + dir + "/f_%d.png").exit_code, 0);
    ASSERT_EQ(test::run_lancer("render " + kScene + " --frames 0-4 -o " + clean + "/f_%d.png").exit_code, 0);
    EXPECT_FALSE(test::file_exists(dir + "/f_5.png")) << "--frames 0-4 renders 0 to 4 only";

    fs::remove(dir + "/f_2.png");
    std::map<int, FileId> before;
    for (int k : {0, 1, 3, 4}) before[k] = file_id(dir + "/f_" + std::to_string(k) + ".png");

    auto r = test::run_lancer("render " + kScene + " --frames 0-4 -o " + dir + "/f_%d.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto rendered = rendered_frame_lines(r.err);
    ASSERT_EQ(rendered.size(), 1u) << r.err;
    EXPECT_EQ(rendered[0].rfind(dir + "/f_2.png: frame 2 (1/1)", 0), 0u) << rendered[0];
    EXPECT_NE(r.err.find("skipping 4 finished frame(s): 0-1, 3-4"), std::string::npos) << r.err;
    for (auto& [k, id] : before) EXPECT_TRUE(same_file(id, file_id(dir + "/f_" + std::to_string(k) + ".png"))) << k;
    for (int k = 0; k < 5; ++k) {
        std::string name = "/f_" + std::to_string(k) + ".png";
        EXPECT_EQ(slurp(dir + name), slurp(clean + name)) << "frame " << k << " differs from a clean run";
    }

    // --force renders every frame again (each is a new file: writes are rename()s).
    auto forced = test::run_lancer("render " + kScene + " --frames 0-4 --force -o " + dir + "/f_%d.png");
    ASSERT_EQ(forced.exit_code, 0) << forced.err;
    EXPECT_EQ(rendered_frame_lines(forced.err).size(), 5u) << forced.err;
    for (auto& [k, id] : before) EXPECT_FALSE(same_file(id, file_id(dir + "/f_" + std::to_string(k) + ".png"))) << k;

    // Nothing left to do: no renderer is even started.
    auto idle = test::run_lancer("render " + kScene + " --frames 0-4 -o " + dir + "/f_%d.png");
    ASSERT_EQ(idle.exit_code, 0) << idle.err;
    EXPECT_TRUE(rendered_frame_lines(idle.err).empty()) << idle.err;
    EXPECT_NE(idle.err.find("nothing to render"), std::string::npos) << idle.err;
}

TEST(AnimationCli, FramesOfAnotherSizeAreRenderedAgain) {
    std::string dir = anim_dir("resize");
    ASSERT_EQ(test::run_lancer("render " + kScene + " --frames 0-1 -o " + dir + "/f_%d.png").exit_code, 0);
    auto r = test::run_lancer("render " + kScene + " --frames 0-1 --width 32 --height 18 -o " + dir + "/f_%d.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(rendered_frame_lines(r.err).size(), 2u) << r.err;
    EXPECT_EQ(read_png(dir + "/f_1.png").width, 32);
}

// A frame rendered inside a sequence (after others, with the GPU's buffers reused and partly
// skipped) is byte for byte the frame rendered alone by a fresh process, as a still.
TEST(AnimationCli, FramesOfASequenceEqualStillsOfTheSameMoment) {
    std::string dir = anim_dir("stills");
    ASSERT_EQ(test::run_lancer("render " + kScene + " -o " + dir + "/f_%d.png").exit_code, 0);
    for (int k : {0, 3, 5}) {
        std::string still = dir + "/still_" + std::to_string(k) + ".png";
        auto r = test::run_lancer("render " + kScene + " --frames " + std::to_string(k) + " -o " + still);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(slurp(still), slurp(dir + "/f_" + std::to_string(k) + ".png")) << "frame " << k;
    }
}

TEST(AnimationCli, QuietPrintsNothing) {
    std::string dir = anim_dir("quiet");
    auto r = test::run_lancer("render " + kScene + " --frames 0-1 -q -o " + dir + "/f_%d.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(files_in(dir), 2u);
}

TEST(AnimationCli, CreatesTheFrameDirectory) {
    std::string dir = anim_dir("mkdir");
    auto r = test::run_lancer("render " + kScene + " --frames 0 -o " + dir + "/new/deeper/f_%d.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(test::file_exists(dir + "/new/deeper/f_0.png"));
}

// On a terminal: one live line (rewritten with \r) with frame i/N, percent, elapsed and ETA,
// and no per-frame log lines. `script` (util-linux, Essential in Debian) gives lancer a pty.
TEST(AnimationCli, TerminalGetsOneLiveLine) {
    std::string dir = anim_dir("tty");
    std::string log = dir + "/typescript";
    std::string inner = "LANCER_VALIDATION=1 " + std::string(LANCER_EXE) + " render " + kScene + " -o " + dir + "/f_%d.png";
    std::string command = "script -qefc '" + inner + "' /dev/null >" + log + " 2>&1 </dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << slurp(log);
    std::string out = slurp(log);
    EXPECT_NE(out.find("\r\033[Kframe 1/6 "), std::string::npos) << out;
    EXPECT_NE(out.find("frame 6/6 "), std::string::npos) << out;
    EXPECT_NE(out.find(" elapsed, ETA "), std::string::npos) << out;
    EXPECT_TRUE(rendered_frame_lines(out).empty()) << "no per-frame lines on a terminal: " << out;
    EXPECT_NE(out.find("rendered 6 frame(s)"), std::string::npos) << out;
}

// ffprobe's view of a video: frames decoded, frame rate.
struct Probe {
    int frames = -1;
    std::string rate;
};
Probe probe(const std::string& video) {
    std::string out = video + ".probe";
    std::string command = "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,r_frame_rate "
                          "-of default=noprint_wrappers=1 '" + video + "' >" + out + " 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << "ffprobe (package ffmpeg, installed by ./setup.sh): " << slurp(out);
    Probe p;
    for (const std::string& line : lines_of(slurp(out))) {
        if (line.rfind("nb_read_frames=", 0) == 0) p.frames = std::stoi(line.substr(15));
        if (line.rfind("r_frame_rate=", 0) == 0) p.rate = line.substr(13);
    }
    return p;
}

class Video : public testing::TestWithParam<std::string> {};

TEST_P(Video, HasEveryFrameAtTheScenesFps) {
    std::string dir = anim_dir("video-" + GetParam());
    std::string video = dir + "/small." + GetParam();
    auto r = test::run_lancer("render " + kScene + " -o " + dir + "/f_%d.png --video " + video);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_TRUE(test::file_exists(video)) << r.err;
    Probe p = probe(video);
    EXPECT_EQ(p.frames, 6);
    EXPECT_EQ(p.rate, "10/1");
    EXPECT_NE(r.err.find(video + ": 6 frames at 10 fps"), std::string::npos) << r.err;
    EXPECT_EQ(files_in(dir), 8u) << "6 frames, the video, its probe: no temporary file left";
}

INSTANTIATE_TEST_SUITE_P(Formats, Video, testing::Values("mp4", "webm", "gif"));

TEST(AnimationCli, VideoWaitsForEveryFrame) {
    std::string dir = anim_dir("video-missing");
    auto r = test::run_lancer("render " + kScene + " --frames 0-2 -o " + dir + "/f_%d.png --video " + dir + "/v.mp4");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(lines_of(r.err).back().find("frame(s) 3-5 of " + dir + "/f_%d.png are missing"), std::string::npos) << r.err;
    EXPECT_FALSE(test::file_exists(dir + "/v.mp4"));
    // Once the other frames exist (rendered elsewhere, say), the video is made without rendering.
    ASSERT_EQ(test::run_lancer("render " + kScene + " --frames 3-5 -o " + dir + "/f_%d.png").exit_code, 0);
    auto again = test::run_lancer("render " + kScene + " -o " + dir + "/f_%d.png --video " + dir + "/v.mp4");
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_TRUE(rendered_frame_lines(again.err).empty()) << again.err;
    EXPECT_EQ(probe(dir + "/v.mp4").frames, 6);
}

// A frame cut short after its header (an interrupted copy in the farm workflow) still says its
// size; it must be rendered again, and the video must hold every frame it claims.
TEST(AnimationCli, ATruncatedFrameIsRenderedAgain) {
    std::string dir = anim_dir("truncated");
    ASSERT_EQ(test::run_lancer("render " + kScene + " -o " + dir + "/f_%d.png").exit_code, 0);
    std::string whole = slurp(dir + "/f_3.png");
    fs::resize_file(dir + "/f_3.png", 60);
    auto r = test::run_lancer("render " + kScene + " -o " + dir + "/f_%d.png --video " + dir + "/v.mp4");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto rendered = rendered_frame_lines(r.err);
    ASSERT_EQ(rendered.size(), 1u) << r.err;
    EXPECT_EQ(rendered[0].rfind(dir + "/f_3.png: frame 3 (1/1)", 0), 0u) << rendered[0];
    EXPECT_NE(r.err.find("rendering frame(s) 3 again: their files do not decode completely at 48x27"), std::string::npos)
        << r.err;
    EXPECT_EQ(slurp(dir + "/f_3.png"), whole);
    EXPECT_EQ(probe(dir + "/v.mp4").frames, 6);
}

// The same cut-short frame is not a frame for --video: it is named as missing rather than
// encoded as whatever ffmpeg makes of it.
TEST(AnimationCli, VideoCountsDecodedFramesNotFiles) {
    std::string dir = anim_dir("truncated-video");
    ASSERT_EQ(test::run_lancer("render " + kScene + " -o " + dir + "/f_%d.png").exit_code, 0);
    fs::resize_file(dir + "/f_2.png", 60);
    auto r = test::run_lancer("render " + kScene + " --frames 0-1 -o " + dir + "/f_%d.png --video " + dir + "/v.mp4");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(lines_of(r.err).back().find("frame(s) 2 of " + dir + "/f_%d.png are missing"), std::string::npos) << r.err;
    EXPECT_FALSE(test::file_exists(dir + "/v.mp4"));
}

// In args, DIR is replaced by the case's empty directory.
using BadCase = test::RejectedCommand;

class AnimationCliRejects : public testing::TestWithParam<BadCase> {};

TEST_P(AnimationCliRejects, WithExitCode2AndOneLineAndNoFiles) {
    const BadCase& c = GetParam();
    std::string dir = anim_dir("bad-" + c.name);
    std::string args = c.args, message = c.message;
    for (std::string* s : {&args, &message})
        for (std::size_t at; (at = s->find("DIR")) != std::string::npos;) s->replace(at, 3, dir);
    auto r = test::run_lancer(args, c.env);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind(message, 0), 0u) << "stderr was: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line expected: " << r.err;
    EXPECT_EQ(files_in(dir), 0u) << "nothing may be written";
}

const std::string kSeed = test::source_path("scenes/seed.toml");

INSTANTIATE_TEST_SUITE_P(
    Cases, AnimationCliRejects,
    testing::Values(
        BadCase{"range_reversed", "render " + kScene + " --frames 4-2 -o DIR/f_%d.png", "",
                "lancer: error: --frames 4-2: the first frame comes after the last"},
        BadCase{"range_too_far", "render " + kScene + " --frames 0-6 -o DIR/f_%d.png", "",
                "lancer: error: --frames 0-6: the animation has 6 frames, 0-5"},
        BadCase{"range_garbage", "render " + kScene + " --frames all -o DIR/f_%d.png", "", "lancer: error: --frames all:"},
        BadCase{"no_pattern", "render " + kScene + " -o DIR/f.png", "",
                "lancer: error: -o DIR/f.png: an animation needs a frame number in the name, such as DIR/f_%d.png"},
        BadCase{"bad_pattern", "render " + kScene + " -o DIR/f_%s.png", "", "lancer: error: -o DIR/f_%s.png: '%s' is not a frame number"},
        BadCase{"two_fields", "render " + kScene + " -o DIR/f_%d_%d.png", "", "lancer: error: -o DIR/f_%d_%d.png: two frame numbers"},
        BadCase{"field_in_directory", "render " + kScene + " -o DIR/%d/f.png", "",
                "lancer: error: -o DIR/%d/f.png: the frame number must be in the file name"},
        BadCase{"video_format", "render " + kScene + " -o DIR/f_%d.png --video DIR/v.avi", "",
                "lancer: error: --video DIR/v.avi: unsupported format '.avi' (use .mp4, .webm or .gif)"},
        BadCase{"video_without_pattern", "render " + kScene + " --frames 2 -o DIR/f.png --video DIR/v.mp4", "",
                "lancer: error: -o DIR/f.png: an animation needs a frame number"},
        // Checked before anything is rendered, with the package to install.
        BadCase{"no_ffmpeg", "render " + kScene + " -o DIR/f_%d.png --video DIR/v.mp4", "PATH=/nonexistent",
                "lancer: error: --video needs ffmpeg, which is not installed (Debian package 'ffmpeg': apt-get install ffmpeg)"},
        BadCase{"still_scene_frames", "render " + kSeed + " --frames 0 -o DIR/f_%d.png", "",
                "lancer: error: " + kSeed + " has no [animation] table, so --frames and --video do not apply"},
        BadCase{"still_scene_pattern", "render " + kSeed + " --width 8 --height 8 -o DIR/f_%d.png", "",
                "lancer: error: -o DIR/f_%d.png: a frame number pattern, but " + kSeed + " has no [animation] table"},
        BadCase{"bad_animation", "render " + test::source_path("tests/data/bad/anim_fps_zero.toml") + " -o DIR/f_%d.png", "",
                test::source_path("tests/data/bad/anim_fps_zero.toml") + ":4:7: error: fps must be between 0.01 and 1000"}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace lancer

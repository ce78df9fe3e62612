// `lancer render` when the world fails it: a full disk, a read-only directory, a file size
// limit, an output path that is a directory, SIGINT and SIGTERM in the middle of a frame. Each
// must end with one clear message and a non-zero exit code, leave no partial or temporary file,
// and leave the frames an animation finished before intact.
//
// The full disk and the read-only directory are real: a small tmpfs, mounted in a private mount
// namespace (unshare; as root, or as anyone where user namespaces are allowed), so nothing
// outside the test sees it. Its files vanish with the namespace, so the script run inside
// copies out what the test checks.
#include <csignal>
#include <filesystem>
#include <regex>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "gpu/vulkan/driver_quirks.hpp"
#include "image/image.hpp"
#include "support/pty_process.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

const std::string kSeed = test::source_path("scenes/seed.toml");

std::string fresh_dir(const std::string& name) { return test::fresh_dir("faults-" + name); }

std::string trim(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    return s;
}

// The last line of `text`, from its "lancer:" on (a terminal's line also holds the escape
// sequence that cleared the live progress line).
std::string last_line(const std::string& text) {
    std::string t = trim(text);
    auto at = t.find_last_of('\n');
    std::string line = at == std::string::npos ? t : t.substr(at + 1);
    auto message = line.find("lancer:");
    return message == std::string::npos ? line : line.substr(message);
}

std::string lancer_command() { return "LANCER_VALIDATION=1 " + std::string(LANCER_EXE); }

// How to get a private mount namespace here: as root, or through a user namespace.
std::string unshare_command() {
    static const std::string command = [] {
        for (std::string c : {"unshare --mount --map-root-user", "unshare --mount"})
            if (std::system((c + " true >/dev/null 2>&1").c_str()) == 0) return c;
        return std::string();
    }();
    return command;
}

// Runs the shell `script` in a private mount namespace in which `dir` is a fresh tmpfs mounted
// with `options` (the script sees $D as that directory). Returns the script's exit status.
int in_private_tmpfs(const std::string& dir, const std::string& options, const std::string& script) {
    EXPECT_NE(unshare_command(), "") << "the fault tests need a private mount namespace: run them as root, or allow "
                                        "user namespaces (sysctl kernel.unprivileged_userns_clone=1)";
    std::string inner = "set -u; D='" + dir + "'; mount -t tmpfs -o " + options + " lancer-test \"$D\" || exit 99; " + script;
    std::string path = dir + ".sh";
    test::write_file(path, inner);
    int status = std::system((unshare_command() + " sh " + path).c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A still image on a disk with one 4 KiB page left: the PNG write fails part way through.
TEST(Faults, DiskFullWhileWritingAStill) {
    std::string dir = fresh_dir("full"), evidence = fresh_dir("full-evidence");
    int status = in_private_tmpfs(dir, "size=1m", R"(
        head -c 2M /dev/zero > "$D/filler" 2>/dev/null; truncate -s -4096 "$D/filler"
        )" + lancer_command() + " render " + kSeed + " --width 200 --height 120 -o \"$D/out.png\" 2> " + evidence + R"(/err
        echo $? > )" + evidence + R"(/code
        ls -A "$D" > )" + evidence + "/listing");
    ASSERT_EQ(status, 0);
    EXPECT_EQ(trim(test::read_file(evidence + "/code")), "2");
    EXPECT_EQ(test::read_file(evidence + "/err"), "lancer: error: cannot write '" + dir + "/out.png': No space left on device\n");
    EXPECT_EQ(trim(test::read_file(evidence + "/listing")), "filler") << "no partial PNG, no temporary file";
}

// An animation whose disk fills after two frames: the third fails, the first two are untouched.
TEST(Faults, DiskFullInAnAnimationKeepsTheFinishedFrames) {
    std::string dir = fresh_dir("full-anim"), evidence = fresh_dir("full-anim-evidence");
    std::string e = evidence;
    const std::string render = lancer_command() + " render " + test::small_animation() + " --width 200 --height 120";
    int status = in_private_tmpfs(dir, "size=1m", render + " --frames 0-1 -o \"$D/f_%d.png\" 2>/dev/null; echo $? > " + e + R"(/code1
        cp "$D/f_0.png" "$D/f_1.png" )" + e + R"(/
        stat -c '%n %i %Y' "$D/f_0.png" "$D/f_1.png" > )" + e + R"(/before
        head -c 2M /dev/zero > "$D/filler" 2>/dev/null; truncate -s -4096 "$D/filler"
        )" + render + " -o \"$D/f_%d.png\" 2> " + e + "/err; echo $? > " + e + R"(/code2
        stat -c '%n %i %Y' "$D/f_0.png" "$D/f_1.png" > )" + e + R"(/after
        cmp "$D/f_0.png" )" + e + "/f_0.png && cmp \"$D/f_1.png\" " + e + "/f_1.png; echo $? > " + e + R"(/same
        ls -A "$D" > )" + e + "/listing");
    ASSERT_EQ(status, 0);
    EXPECT_EQ(trim(test::read_file(e + "/code1")), "0");
    EXPECT_EQ(trim(test::read_file(e + "/code2")), "2");
    EXPECT_EQ(last_line(test::read_file(e + "/err")),
              "lancer: error: cannot write '" + dir + "/f_2.png': No space left on device");
    EXPECT_EQ(test::read_file(e + "/before"), test::read_file(e + "/after")) << "frames 0 and 1 were rewritten";
    EXPECT_EQ(trim(test::read_file(e + "/same")), "0") << "frames 0 and 1 changed";
    EXPECT_EQ(trim(test::read_file(e + "/listing")), "f_0.png\nf_1.png\nfiller");
    EXPECT_EQ(read_png(e + "/f_1.png").width, 200);
}

// A read-only file system (where even root cannot write): refused before rendering, for a
// still, for frames, and for a frame directory that would have to be created there.
TEST(Faults, ReadOnlyDirectory) {
    std::string dir = fresh_dir("readonly"), e = fresh_dir("readonly-evidence");
    int status = in_private_tmpfs(dir, "ro,size=64k",
        lancer_command() + " render " + kSeed + " --width 32 --height 18 -o \"$D/out.png\" 2> " + e + "/err1; echo $? > " + e + "/code1\n" +
        lancer_command() + " render " + test::small_animation() + " -o \"$D/f_%d.png\" 2> " + e + "/err2; echo $? > " + e + "/code2\n" +
        lancer_command() + " render " + test::small_animation() + " -o \"$D/frames/f_%d.png\" 2> " + e + "/err3; echo $? > " + e + "/code3\n" +
        "ls -A \"$D\" > " + e + "/listing");
    ASSERT_EQ(status, 0);
    for (const char* n : {"1", "2", "3"}) EXPECT_EQ(trim(test::read_file(e + "/code" + n)), "2") << n;
    EXPECT_EQ(test::read_file(e + "/err1"), "lancer: error: cannot write '" + dir + "/out.png': directory '" + dir + "' is not writable\n");
    EXPECT_EQ(test::read_file(e + "/err2"), "lancer: error: cannot write '" + dir + "/f_0.png': directory '" + dir + "' is not writable\n");
    EXPECT_EQ(test::read_file(e + "/err3"),
              "lancer: error: cannot create the frame directory '" + dir + "/frames': Read-only file system\n");
    EXPECT_EQ(trim(test::read_file(e + "/listing")), "");
}

// A file size limit (ulimit -f) turns the write into EFBIG instead of killing lancer with
// SIGXFSZ half way through the file.
TEST(Faults, FileSizeLimit) {
    std::string dir = fresh_dir("fsize");
    std::string command = "bash -c 'ulimit -f 4; " + lancer_command() + " render " + kSeed +
                          " --backend cpu --width 200 --height 120 -o " + dir + "/out.png' 2> " + dir + ".err";
    int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2);
    EXPECT_EQ(test::read_file(dir + ".err"), "lancer: error: cannot write '" + dir + "/out.png': File too large\n");
    EXPECT_EQ(test::listing(dir), "");
}

// On the GPU path the limit also bounds the file lavapipe from Mesa 25 keeps device memory in
// (gpu/vulkan/driver_quirks.hpp), which it grows without checking and then dies of SIGBUS: refused
// first. Where the driver does not, the output write fails as above.
TEST(Faults, FileSizeLimitOnTheGpuPath) {
    std::string dir = fresh_dir("fsize-gpu");
    std::string command = "bash -c 'ulimit -f 4; " + lancer_command() + " render " + kSeed +
                          " --width 200 --height 120 -o " + dir + "/out.png' 2> " + dir + ".err";
    int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 2);
    if (gpu::keeps_device_memory_in_a_file(test::gpu_renderer().context().info()))
        EXPECT_EQ(test::read_file(dir + ".err"),
                  "lancer: error: lavapipe keeps the GPU's memory in a file, and the file size limit (ulimit -f) of "
                  "4096 bytes is too small for it: this render needs up to 1 MiB; raise the limit (ulimit -f "
                  "unlimited) or render with --backend cpu\n");
    else
        EXPECT_EQ(test::read_file(dir + ".err"), "lancer: error: cannot write '" + dir + "/out.png': File too large\n");
    EXPECT_EQ(test::listing(dir), "");
}

// A limit that holds the driver's file but not this render's buffers: refused before rendering.
TEST(Faults, FileSizeLimitBelowARendersBuffers) {
    if (!gpu::keeps_device_memory_in_a_file(test::gpu_renderer().context().info()))
        GTEST_SKIP() << "this driver does not keep device memory in a file";
    std::string dir = fresh_dir("fsize-buffers");
    std::string command = "bash -c 'ulimit -f 2048; " + lancer_command() + " render " +
                          test::source_path("scenes/cornell.toml") + " --width 64 --height 36 -o " + dir +
                          "/out.png' 2> " + dir + ".err";
    int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 2);
    EXPECT_NE(test::read_file(dir + ".err").find("the file size limit (ulimit -f) of 2 MiB is too small"), std::string::npos)
        << test::read_file(dir + ".err");
    EXPECT_EQ(test::listing(dir), "");
}

// A frame path that is a directory, met after frame 0 was written: frame 0 stays.
TEST(Faults, AFramePathThatIsADirectoryStopsTheAnimation) {
    std::string dir = fresh_dir("frame-dir");
    fs::create_directory(dir + "/f_1.png");
    auto r = test::run_lancer("render " + test::small_animation() + " --frames 0-2 -o " + dir + "/f_%d.png");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(last_line(r.err), "lancer: error: cannot write '" + dir + "/f_1.png': it is a directory");
    EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
    EXPECT_EQ(test::listing(dir), "f_0.png f_1.png ");
    EXPECT_EQ(read_png(dir + "/f_0.png").width, 48);
}

// The live line's last percentage, -1 before there is one.
int last_percent(const std::string& output) {
    static const std::regex percent(R"(\s(\d+)%)");
    int last = -1;
    for (auto it = std::sregex_iterator(output.begin(), output.end(), percent); it != std::sregex_iterator(); ++it)
        last = std::stoi((*it)[1]);
    return last;
}

struct InterruptCase {
    std::string backend;
    int signal_number;
};

std::string name_of(const InterruptCase& c) { return c.backend + (c.signal_number == SIGINT ? "_SIGINT" : "_SIGTERM"); }
void PrintTo(const InterruptCase& c, std::ostream* os) { *os << name_of(c); }

class Interrupt : public testing::TestWithParam<InterruptCase> {};

// A still image far too large to finish: the signal arrives once the live line shows that part
// of it is done and more is to come.
TEST_P(Interrupt, InTheMiddleOfAStillWritesNothing) {
    const InterruptCase& c = GetParam();
    std::string dir = fresh_dir("interrupt-still-" + name_of(c));
    std::string out = dir + "/out.png";
    test::PtyProcess lancer({"render", kSeed, "--backend", c.backend, "--width", "1024", "--height", "1024", "--samples", "8",
                             "-o", out});
    ASSERT_TRUE(lancer.read_until([](const std::string& s) {
        int p = last_percent(s);
        return p >= 1 && p < 100;
    })) << lancer.output();
    lancer.send(c.signal_number);
    EXPECT_EQ(lancer.wait_exit(), 128 + c.signal_number) << lancer.output();
    std::string expected = "lancer: interrupted by " + std::string(c.signal_number == SIGINT ? "SIGINT" : "SIGTERM") +
                           ": '" + out + "' was not written";
    EXPECT_EQ(last_line(lancer.output()), expected) << lancer.output();
    EXPECT_EQ(lancer.output().find("validation"), std::string::npos) << lancer.output();
    EXPECT_EQ(test::listing(dir), "") << "no partial PNG, no temporary file";
}

// An animation interrupted while its second frame is half done: the first frame is complete and
// untouched, nothing else is written.
TEST_P(Interrupt, InTheMiddleOfAFrameKeepsTheFramesBefore) {
    const InterruptCase& c = GetParam();
    std::string dir = fresh_dir("interrupt-anim-" + name_of(c));
    test::PtyProcess lancer({"render", test::small_animation(), "--backend", c.backend, "--frames", "0-3", "--width", "640", "--height",
                             "480", "--samples", "4", "-o", dir + "/f_%d.png"});
    std::string frame0;
    ASSERT_TRUE(lancer.read_until([&](const std::string& s) {
        auto at = s.rfind("frame 2/4 ");
        if (at == std::string::npos) return false;
        int p = last_percent(s.substr(at));
        return p >= 1 && p < 100;
    })) << lancer.output();
    frame0 = test::read_file(dir + "/f_0.png");
    struct stat before {};
    ASSERT_EQ(::stat((dir + "/f_0.png").c_str(), &before), 0);
    lancer.send(c.signal_number);
    EXPECT_EQ(lancer.wait_exit(), 128 + c.signal_number) << lancer.output();
    EXPECT_EQ(last_line(lancer.output()),
              "lancer: interrupted by " + std::string(c.signal_number == SIGINT ? "SIGINT" : "SIGTERM") + ": frame 1 ('" +
                  dir + "/f_1.png') was not written; frame(s) 0 are complete; run the same command again to resume")
        << lancer.output();
    EXPECT_EQ(lancer.output().find("validation"), std::string::npos) << lancer.output();
    EXPECT_EQ(test::listing(dir), "f_0.png ") << "no partial frame, no temporary file";
    struct stat after {};
    ASSERT_EQ(::stat((dir + "/f_0.png").c_str(), &after), 0);
    EXPECT_EQ(before.st_ino, after.st_ino);
    EXPECT_EQ(test::read_file(dir + "/f_0.png"), frame0);
    EXPECT_EQ(read_png(dir + "/f_0.png").width, 640);
}

INSTANTIATE_TEST_SUITE_P(Cases, Interrupt,
                         testing::Values(InterruptCase{"gpu", SIGINT}, InterruptCase{"gpu", SIGTERM},
                                         InterruptCase{"cpu", SIGINT}, InterruptCase{"cpu", SIGTERM}),
                         [](const auto& info) { return name_of(info.param); });

}  // namespace
}  // namespace lancer

// SIGINT and SIGTERM in every phase of a run: loading (a FIFO as the scene or as a
// texture, which blocks the open until a writer comes), the pipeline compile, encoding a video.
// Each run must end promptly with the interrupted line and 128 + the signal, and leave nothing
// behind: no temporary file, no ffmpeg. (The dispatch phase: Interrupt.* in faults_test.cpp.)
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "support/pty_process.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;


std::string signal_text(int signal_number) { return signal_number == SIGINT ? "SIGINT" : "SIGTERM"; }

// The last line that starts with "lancer:" (a terminal's output also holds live lines).
std::string last_message(const std::string& text) {
    auto at = text.rfind("lancer:");
    if (at == std::string::npos) return "";
    std::string line = text.substr(at);
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    return line;
}

// Whether process `pid` is blocked in an open of a file (openat, syscall 257 on x86-64), as
// /proc says: a bounded wait on the process's state, not a sleep.
bool wait_until_blocked_in_open(pid_t pid, std::chrono::seconds timeout = 60s) {
    auto until = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < until) {
        std::ifstream in("/proc/" + std::to_string(pid) + "/syscall");
        long number = -1;
        if (in >> number && number == 257) return true;
        std::this_thread::sleep_for(20ms);
    }
    return false;
}

class Signals : public testing::TestWithParam<int> {};

std::string name_of(int signal_number) { return signal_text(signal_number); }

// The scene is a FIFO nobody writes to: lancer waits in open(). One signal must end it (a
// handler installed with SA_RESTART would restart the open and swallow the signal).
TEST_P(Signals, WhileOpeningAFifoAsTheScene) {
    const int sig = GetParam();
    std::string dir = test::fresh_dir("signals-fifo-scene-" + name_of(sig));
    std::string fifo = dir + "/scene.toml";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    test::PtyProcess lancer({"render", fifo, "-o", dir + "/out.png"});
    ASSERT_TRUE(wait_until_blocked_in_open(lancer.pid()));
    lancer.send(sig);
    EXPECT_EQ(lancer.wait_exit(10s), 128 + sig) << lancer.output();
    EXPECT_EQ(last_message(lancer.output()), "lancer: interrupted by " + signal_text(sig) + ": nothing was written");
    EXPECT_EQ(test::listing(dir), "scene.toml ");
}

TEST_P(Signals, WhileOpeningAFifoAsATexture) {
    const int sig = GetParam();
    std::string dir = test::fresh_dir("signals-fifo-texture-" + name_of(sig));
    ASSERT_EQ(::mkfifo((dir + "/wood.png").c_str(), 0600), 0);
    test::write_file(dir + "/scene.toml", R"(
        [camera]
        eye = [0, 0, -5]
        look_at = [0, 0, 0]
        [material.ball]
        texture = "wood.png"
        [[object]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
        material = "ball"
    )");
    test::PtyProcess lancer({"render", dir + "/scene.toml", "-o", dir + "/out.png"});
    ASSERT_TRUE(wait_until_blocked_in_open(lancer.pid()));
    lancer.send(sig);
    EXPECT_EQ(lancer.wait_exit(10s), 128 + sig) << lancer.output();
    EXPECT_EQ(last_message(lancer.output()), "lancer: interrupted by " + signal_text(sig) + ": nothing was written");
    EXPECT_EQ(test::listing(dir), "scene.toml wood.png ");
}

// `lancer watch` on a FIFO: the signal that ends watch (exit code 0) must not be swallowed.
TEST_P(Signals, WatchWhileOpeningAFifo) {
    const int sig = GetParam();
    std::string dir = test::fresh_dir("signals-fifo-watch-" + name_of(sig));
    std::string fifo = dir + "/scene.toml";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    test::PtyProcess lancer({"watch", fifo, "-o", dir + "/out.png"});
    ASSERT_TRUE(wait_until_blocked_in_open(lancer.pid()));
    lancer.send(sig);
    EXPECT_EQ(lancer.wait_exit(10s), 0) << lancer.output();
}

// ffmpeg is a stand-in that never finishes (a slow encoder): the signal must stop it, remove
// its temporary file and end lancer with the interrupted line.
TEST_P(Signals, WhileEncodingAVideo) {
    const int sig = GetParam();
    std::string dir = test::fresh_dir("signals-video-" + name_of(sig));
    std::string bin = dir + "/bin";
    fs::create_directories(bin);
    test::write_file(bin + "/ffmpeg", "#!/bin/sh\necho $$ > \"" + dir + "/ffmpeg.pid\"\nexec sleep 1000\n");
    fs::permissions(bin + "/ffmpeg", fs::perms::owner_all);
    std::string frames = dir + "/frames";
    const char* old_path = std::getenv("PATH");
    std::string saved = old_path ? old_path : "";
    ::setenv("PATH", (bin + ":" + saved).c_str(), 1);
    test::PtyProcess lancer({"render", test::small_animation(), "-o", frames + "/f_%d.png", "--video", dir + "/out.webm"});
    ::setenv("PATH", saved.c_str(), 1);
    ASSERT_TRUE(lancer.read_until([](const std::string& s) { return s.find("encoding 6 frames") != std::string::npos; }))
        << lancer.output();
    // The stand-in has started once it wrote its pid.
    auto until = std::chrono::steady_clock::now() + 30s;
    while (!test::file_exists(dir + "/ffmpeg.pid") && std::chrono::steady_clock::now() < until)
        std::this_thread::sleep_for(20ms);
    ASSERT_TRUE(test::file_exists(dir + "/ffmpeg.pid"));
    lancer.send(sig);
    EXPECT_EQ(lancer.wait_exit(10s), 128 + sig) << lancer.output();
    EXPECT_EQ(last_message(lancer.output()), "lancer: interrupted by " + signal_text(sig) + ": '" + dir +
                                                 "/out.webm' was not written; the frames are complete");
    EXPECT_EQ(test::listing(dir), "bin ffmpeg.pid frames ") << "no video, no hidden temporary";
    EXPECT_EQ(test::listing(frames), "f_0.png f_1.png f_2.png f_3.png f_4.png f_5.png ");
    pid_t ffmpeg = std::stoi(test::read_file(dir + "/ffmpeg.pid"));
    EXPECT_NE(::kill(ffmpeg, 0), 0) << "the stand-in ffmpeg still runs";
}

// The driver's compile of a tracer with the largest expression surfaces accepted (two of 256
// operations: several seconds of LLVM, more on a loaded machine), with Mesa's shader cache off
// so that it is really compiled. The live line shows 0 % while lancer waits for the compile on
// its worker thread; the signal must end lancer at once, not when LLVM is done.
TEST_P(Signals, WhileTheDriverCompilesThePipeline) {
    const int sig = GetParam();
    std::string dir = test::fresh_dir("signals-compile-" + name_of(sig));
    std::string product;
    for (int i = 0; i < 256; ++i) product += (i ? "*" : "") + std::string(i % 2 ? "v" : "u");  // 255 operations
    std::string surfaces;
    for (int k = 0; k < 2; ++k)
        surfaces += "[[object]]\ntype = \"parametric\"\nx = \"u + " + std::to_string(2 * k) + "\"\ny = \"v\"\nz = \"" +
                    product + "\"\nu = [0, 1]\nv = [0, 1]\n";  // and x's addition: 256
    test::write_file(dir + "/scene.toml", "[render]\nwidth = 32\nheight = 18\nsamples = 1\n[camera]\neye = [1.5, 0.5, -4]\n"
                                          "look_at = [1.5, 0.5, 0]\n[[light]]\nposition = [0, 3, -5]\n" + surfaces);
    ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    test::PtyProcess lancer({"render", dir + "/scene.toml", "-o", dir + "/out.png"});
    ::unsetenv("MESA_SHADER_CACHE_DISABLE");
    ASSERT_TRUE(lancer.read_until([](const std::string& s) { return s.find(" 0%") != std::string::npos; }))
        << lancer.output();
    lancer.send(sig);
    auto sent = std::chrono::steady_clock::now();
    EXPECT_EQ(lancer.wait_exit(60s), 128 + sig) << lancer.output();
    // Bounded generously for a loaded machine; waiting for the compile took minutes.
    EXPECT_LT(std::chrono::steady_clock::now() - sent, 10s);
    EXPECT_EQ(last_message(lancer.output()),
              "lancer: interrupted by " + signal_text(sig) + ": '" + dir + "/out.png' was not written");
    EXPECT_EQ(test::listing(dir), "scene.toml ");
}

INSTANTIATE_TEST_SUITE_P(Each, Signals, testing::Values(SIGINT, SIGTERM), [](const auto& info) { return name_of(info.param); });

}  // namespace
}  // namespace lancer

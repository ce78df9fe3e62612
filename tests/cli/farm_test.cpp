// The farm recipes of docs/farm.md, run as written: GNU parallel over "ssh" to two hosts (an
// ssh stand-in that runs the jobs here) and the Slurm array script, task by task. Either way the
// frames must be byte for byte those of one machine rendering the whole sequence.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "image/image.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

constexpr int kFrames = test::kSmallAnimationFrames;

std::string farm_dir(const std::string& name) { return test::fresh_dir("farm-" + name); }

// Runs a shell command in `dir` (stdout and stderr to dir/log.txt); returns its exit code.
int run_in(const std::string& dir, const std::string& command) {
    std::string line = "cd '" + dir + "' && " + command + " >log.txt 2>&1 </dev/null";
    int status = std::system(line.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Every job's lancer runs under the validation layer: a message fails its job.
std::string lancer_env() { return std::string("LANCER='") + LANCER_EXE + "' LANCER_VALIDATION=1 "; }

// The whole sequence rendered by one machine, in dir/single.
void render_on_one_machine(const std::string& dir) {
    auto r = test::run_lancer("render " + test::small_animation() + " -q -o " + dir + "/single/f_%d.png");
    ASSERT_EQ(r.exit_code, 0) << r.err;
}

void expect_same_frames(const std::string& dir, const std::string& sub) {
    for (int k = 0; k < kFrames; ++k) {
        std::string name = "/f_" + std::to_string(k) + ".png";
        ASSERT_TRUE(test::file_exists(dir + "/" + sub + name)) << sub << name << "\n" << test::read_file(dir + "/log.txt");
        EXPECT_EQ(test::read_file(dir + "/" + sub + name), test::read_file(dir + "/single" + name)) << sub << name;
    }
}

TEST(Farm, GnuParallelOverSshToTwoHostsRendersTheSameFrames) {
    std::string dir = farm_dir("parallel");
    render_on_one_machine(dir);
    fs::create_directories(dir + "/farm");
    // Chunks of 2 frames: three jobs over hostA and hostB, one job at a time on each. HOME is an
    // ancestor of the jobs' directory, as when the frames go under a user's home on the farm, so
    // parallel sends the directory relative to HOME and the remote side must resolve it there.
    // SHELL is unset, as under CI: the remote side must get it from "sshd", not from the caller.
    std::string command = lancer_env() + "HOME='" + test::output_dir() + "' FAKE_SSH_LOG=ssh.log PARALLEL_SSH='" +
                          test::source_path("tests/data/farm/fake-ssh") + "' env -u SHELL '" +
                          test::source_path("docs/farm/render-parallel.sh") + "' '" + test::small_animation() +
                          "' farm/f_%d.png 6 1/hostA,1/hostB 2";
    ASSERT_EQ(run_in(dir, command), 0) << test::read_file(dir + "/log.txt");
    std::string hosts = test::read_file(dir + "/ssh.log");
    EXPECT_GE(test::count_occurrences(hosts, "hostA"), 1) << hosts;
    EXPECT_GE(test::count_occurrences(hosts, "hostB"), 1) << hosts;
    EXPECT_EQ(test::count_occurrences(hosts, "host"), 3) << "one ssh per job: " << hosts;
    expect_same_frames(dir, "farm");

    // Run again after losing a frame: only that frame is rendered, the others are kept.
    fs::remove(dir + "/farm/f_3.png");
    auto before = fs::last_write_time(dir + "/farm/f_0.png");
    ASSERT_EQ(run_in(dir, command), 0) << test::read_file(dir + "/log.txt");
    expect_same_frames(dir, "farm");
    EXPECT_EQ(fs::last_write_time(dir + "/farm/f_0.png"), before);
}

// parallel counts a job as done when its ssh exits 0, which a broken host can do having run
// nothing; the recipe then fails, naming what is missing, instead of reporting success.
TEST(Farm, GnuParallelFailsWhenAHostRendersNothing) {
    std::string dir = farm_dir("parallel-idle-host");
    fs::create_directories(dir + "/farm");
    std::string command = lancer_env() + "PARALLEL_SSH=true '" + test::source_path("docs/farm/render-parallel.sh") +
                          "' '" + test::small_animation() + "' farm/f_%03d.png 6 1/hostA 2";
    EXPECT_EQ(run_in(dir, command), 1);
    std::string log = test::read_file(dir + "/log.txt");
    EXPECT_NE(log.find("6 of 6 frames missing"), std::string::npos) << log;
    EXPECT_NE(log.find("farm/f_000.png"), std::string::npos) << log;
}

TEST(Farm, SlurmArrayTasksTogetherRenderTheSequence) {
    std::string dir = farm_dir("slurm");
    render_on_one_machine(dir);
    fs::create_directories(dir + "/farm");
    std::string script = "'" + test::source_path("docs/farm/render-array.sbatch") + "' '" + test::small_animation() + "' farm/f_%d.png 6 4";
    // Chunks of 4: task 0 renders 0-3, task 1 renders 4-5, task 2 finds nothing left.
    for (int task = 0; task < 3; ++task) {
        std::string env = lancer_env() + "SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " SLURM_CPUS_PER_TASK=2 ";
        ASSERT_EQ(run_in(dir, env + script), 0) << "task " << task << ": " << test::read_file(dir + "/log.txt");
        if (task == 2) {
            EXPECT_NE(test::read_file(dir + "/log.txt").find("no frames left"), std::string::npos);
        }
    }
    expect_same_frames(dir, "farm");

    // Outside a job array the script says what is missing instead of guessing a task.
    EXPECT_NE(run_in(dir, lancer_env() + script), 0);
    EXPECT_NE(test::read_file(dir + "/log.txt").find("SLURM_ARRAY_TASK_ID"), std::string::npos);
}

// The passes of one photon-mapped still, spread over two hosts by the GNU parallel recipe, then
// combined: the image one machine renders, up to float rounding in the combination (each part
// holds the mean of its passes; a missing or doubled pass would move every pixel by a tenth).
TEST(Farm, PhotonPassesOnTwoHostsCombineIntoTheStillOfOneMachine) {
    const std::string scene = test::source_path("tests/data/photons/small.toml");  // 6 passes
    std::string dir = farm_dir("passes");
    auto single = test::run_lancer("render " + scene + " --backend cpu -q -o " + dir + "/single.exr");
    ASSERT_EQ(single.exit_code, 0) << single.err;
    std::string command = lancer_env() + "LANCER_ARGS='--backend cpu' HOME='" + test::output_dir() +
                          "' FAKE_SSH_LOG=ssh.log PARALLEL_SSH='" + test::source_path("tests/data/farm/fake-ssh") +
                          "' env -u SHELL '" + test::source_path("docs/farm/render-passes-parallel.sh") + "' '" + scene +
                          "' farm.exr 6 1/hostA,1/hostB 2";
    ASSERT_EQ(run_in(dir, command), 0) << test::read_file(dir + "/log.txt");
    std::string hosts = test::read_file(dir + "/ssh.log");
    EXPECT_GE(test::count_occurrences(hosts, "hostA"), 1) << hosts;
    EXPECT_GE(test::count_occurrences(hosts, "hostB"), 1) << hosts;
    EXPECT_EQ(test::count_occurrences(hosts, "host"), 3) << "one ssh per part: " << hosts;
    auto expect_single = [&] {
        ExrInfo info;
        FloatImage a = read_exr(dir + "/single.exr"), b = read_exr(dir + "/farm.exr", &info);
        EXPECT_EQ(info.passes, 6);
        ASSERT_EQ(a.pixels.size(), b.pixels.size());
        float largest = 0.0f, worst = 0.0f;
        for (std::size_t i = 0; i < a.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                largest = std::max(largest, a.pixels[i][c]);
                worst = std::max(worst, std::abs(a.pixels[i][c] - b.pixels[i][c]));
            }
        EXPECT_GT(largest, 0.0f);
        EXPECT_LE(worst, 1e-6f * largest);
    };
    expect_single();

    // A lost part is rendered again, and only it.
    fs::remove(dir + "/farm.exr.parts/2-3.exr");
    auto before = fs::last_write_time(dir + "/farm.exr.parts/0-1.exr");
    ASSERT_EQ(run_in(dir, command), 0) << test::read_file(dir + "/log.txt");
    EXPECT_EQ(test::count_occurrences(test::read_file(dir + "/ssh.log"), "host"), 4);
    EXPECT_EQ(fs::last_write_time(dir + "/farm.exr.parts/0-1.exr"), before);
    expect_single();

    // Combining an incomplete set names the passes that are missing.
    auto partial = test::run_lancer("combine " + dir + "/farm.exr.parts/0-1.exr " + dir + "/farm.exr.parts/4-5.exr -o " +
                                    dir + "/partial.png");
    EXPECT_EQ(partial.exit_code, 2);
    EXPECT_NE(partial.err.find("passes 2-3 are missing"), std::string::npos) << partial.err;
    EXPECT_FALSE(test::file_exists(dir + "/partial.png"));
    auto twice = test::run_lancer("combine " + dir + "/farm.exr.parts/0-1.exr " + dir + "/farm.exr.parts/0-1.exr -o " +
                                  dir + "/twice.png");
    EXPECT_EQ(twice.exit_code, 2);
    EXPECT_NE(twice.err.find("hold the same passes"), std::string::npos) << twice.err;
}

}  // namespace
}  // namespace lancer

#include "cli/video.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <csignal>
#include <filesystem>
#include <optional>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include "cli/interrupt.hpp"
#include "core/cancel.hpp"
#include "core/error.hpp"
#include "core/temporary_name.hpp"

extern char** environ;

namespace lancer {
namespace {

std::string extension_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

std::vector<std::string> encoder_arguments(const std::string& ext) {
    // yuv420p is what players expect, and it needs even sizes.
    const std::string pad = "pad=ceil(iw/2)*2:ceil(ih/2)*2";
    if (ext == ".mp4")
        return {"-vf", pad, "-c:v", "libx264", "-preset", "medium", "-crf", "18", "-pix_fmt", "yuv420p",
                "-movflags", "+faststart", "-f", "mp4"};
    if (ext == ".webm")
        return {"-vf", pad, "-c:v", "libvpx-vp9", "-crf", "30", "-b:v", "0", "-row-mt", "1", "-pix_fmt", "yuv420p",
                "-f", "webm"};
    // A GIF has 256 colours: one palette computed from all frames keeps gradients clean.
    return {"-filter_complex", "[0:v]split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse", "-loop", "0",
            "-f", "gif"};
}

struct Result {
    int exit_code;
    std::string err;
};

// Runs `program` with `args`, stdin and stdout on /dev/null, and collects its stderr. A SIGINT or
// SIGTERM to lancer while it runs stops it (SIGKILL: its output is thrown away anyway) and
// returns nullopt; so does the program's own exit while an interrupt is pending (Ctrl-C on a
// terminal reaches the whole process group, ffmpeg too).
std::optional<Result> run(const std::string& program, const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);

    int pipe_fds[2];
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
    // The child starts with lancer's handlers reset to the defaults (exec does that) and no
    // signal blocked.
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
    pid_t pid = 0;
    int spawn_error = ::posix_spawn(&pid, program.c_str(), &actions, &attributes, argv.data(), environ);
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    ::close(pipe_fds[1]);
    if (spawn_error != 0) {
        ::close(pipe_fds[0]);
        throw UserError(fmt::format("cannot run {}: {}", program, std::strerror(spawn_error)));
    }
    Interrupts interrupts;
    std::string err;
    char buffer[4096];
    bool killed = false;
    for (;;) {
        if (interrupts.requested() && !killed) {
            ::kill(pid, SIGKILL);
            killed = true;
        }
        pollfd fds[2] = {{pipe_fds[0], POLLIN, 0}, {interrupts.fd(), POLLIN, 0}};
        if (::poll(fds, killed || interrupts.fd() < 0 ? 1 : 2, -1) < 0) {
            if (errno == EINTR) continue;
            break;
        }
        if (!(fds[0].revents & (POLLIN | POLLHUP | POLLERR))) continue;
        ssize_t n = ::read(pipe_fds[0], buffer, sizeof buffer);
        if (n > 0) err.append(buffer, static_cast<std::size_t>(n));
        else if (n == 0 || errno != EINTR) break;
    }
    ::close(pipe_fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (interrupts.requested()) return std::nullopt;
    int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return Result{code, err};
}

std::string last_line(const std::string& text) {
    std::size_t end = text.find_last_not_of("\r\n \t");
    if (end == std::string::npos) return "no message";
    std::size_t start = text.find_last_of('\n', end);
    return text.substr(start == std::string::npos ? 0 : start + 1, end + 1 - (start == std::string::npos ? 0 : start + 1));
}

}  // namespace

std::string find_program(const std::string& name) {
    const char* env = std::getenv("PATH");
    std::string path = env ? env : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= path.size()) {
        std::size_t end = path.find(':', start);
        if (end == std::string::npos) end = path.size();
        std::string dir = path.substr(start, end - start);
        std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + name;
        struct stat st {};
        if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(candidate.c_str(), X_OK) == 0)
            return candidate;
        start = end + 1;
    }
    return "";
}

void check_video_possible(const std::string& path) {
    std::string ext = extension_of(path);
    if (ext != ".mp4" && ext != ".webm" && ext != ".gif")
        throw UserError(fmt::format("--video {}: unsupported format '{}' (use .mp4, .webm or .gif)", path, ext));
    if (find_program("ffmpeg").empty())
        throw UserError("--video needs ffmpeg, which is not installed (Debian package 'ffmpeg': apt-get install ffmpeg)");
}

void make_video(const std::string& pattern, int frames, double fps, const std::string& output) {
    std::string ffmpeg = find_program("ffmpeg");
    if (ffmpeg.empty()) check_video_possible(output);  // throws the message about the package

    std::string temp = temporary_template(output);
    int fd = ::mkstemp(temp.data());
    if (fd < 0) throw UserError(fmt::format("cannot write '{}': {}", output, std::strerror(errno)));
    ::close(fd);

    // "file:" keeps ffmpeg from reading a colon in a path as a protocol name.
    std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-nostdin", "-y",
                                     "-f", "image2", "-pattern_type", "sequence", "-start_number", "0",
                                     "-framerate", fmt::format("{}", fps), "-i", "file:" + pattern,
                                     "-frames:v", std::to_string(frames)};
    for (std::string& a : encoder_arguments(extension_of(output))) args.push_back(std::move(a));
    args.push_back("file:" + temp);

    std::optional<Result> ran;
    try {
        ran = run(ffmpeg, args);
    } catch (...) {
        ::unlink(temp.c_str());
        throw;
    }
    if (!ran) {
        ::unlink(temp.c_str());
        throw Interrupted(cancellation_signal(), fmt::format("'{}' was not written; the frames are complete", output));
    }
    const Result& r = *ran;
    if (r.exit_code != 0) {
        ::unlink(temp.c_str());
        throw UserError(fmt::format("ffmpeg could not make '{}' (exit code {}): {}", output, r.exit_code, last_line(r.err)));
    }
    if (::chmod(temp.c_str(), 0644) != 0 || ::rename(temp.c_str(), output.c_str()) != 0) {
        std::string message = fmt::format("cannot write '{}': {}", output, std::strerror(errno));
        ::unlink(temp.c_str());
        throw UserError(message);
    }
}

}  // namespace lancer

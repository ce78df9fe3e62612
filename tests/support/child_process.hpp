#pragma once
// A lancer process running beside a test (for `lancer watch`), its stderr captured in a file,
// observed by bounded waits on what it writes — never by fixed sleeps.
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace lancer::test {

// In a forked child: replaces it with LANCER_EXE `args`, with LANCER_VALIDATION=1 (exit code 127
// if that fails).
[[noreturn]] void exec_lancer(const std::vector<std::string>& args);

class ChildProcess {
public:
    // Runs LANCER_EXE with `args` in `cwd`, with LANCER_VALIDATION=1, stderr to `log_path`.
    ChildProcess(const std::vector<std::string>& args, const std::string& cwd, const std::string& log_path);
    ~ChildProcess();  // kills the process if it is still running

    // The captured stderr so far.
    std::string log() const;
    // Polls until `ready()` holds or `timeout` passes; returns whether it held.
    static bool wait_until(const std::function<bool()>& ready, std::chrono::seconds timeout = std::chrono::seconds(60));
    bool running();
    void interrupt();  // SIGINT
    // Waits for exit; returns the exit code, or -1 on timeout.
    int wait_exit(std::chrono::seconds timeout = std::chrono::seconds(30));

private:
    pid_t pid_ = -1;
    std::string log_path_;
    int exit_code_ = -1;
};

}  // namespace lancer::test

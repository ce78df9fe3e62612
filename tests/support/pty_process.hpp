#pragma once
// `lancer` on a pseudo-terminal, as a user runs it: its live progress line is what a test waits
// for (a bounded wait on what it prints, never a fixed sleep), and signals go to it as Ctrl-C
// from a shell would.
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace lancer::test {

class PtyProcess {
public:
    // Runs LANCER_EXE with `args`, with LANCER_VALIDATION=1, stdout and stderr on a new pty.
    explicit PtyProcess(const std::vector<std::string>& args);
    ~PtyProcess();  // kills the process if it is still running
    PtyProcess(const PtyProcess&) = delete;
    PtyProcess& operator=(const PtyProcess&) = delete;

    // Reads what the process prints until `seen(output so far)` holds, the process closes the
    // terminal, or `timeout` passes; returns whether it held.
    bool read_until(const std::function<bool(const std::string&)>& seen,
                    std::chrono::seconds timeout = std::chrono::seconds(120));
    void send(int signal_number);
    // Reads the rest of the output and waits for the exit; the exit code (128 + signal when killed
    // by one), or -1 on timeout.
    int wait_exit(std::chrono::seconds timeout = std::chrono::seconds(120));
    const std::string& output() const { return output_; }
    pid_t pid() const { return pid_; }

private:
    bool read_some(int timeout_ms);  // false at end of output

    pid_t pid_ = -1;
    int master_ = -1;
    int exit_code_ = -1;
    std::string output_;
};

}  // namespace lancer::test

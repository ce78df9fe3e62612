#include "support/pty_process.hpp"

#include "support/child_process.hpp"

#include <csignal>

#include <poll.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

namespace lancer::test {

PtyProcess::PtyProcess(const std::vector<std::string>& args) {
    winsize size{};
    size.ws_col = 200;  // wide enough for the whole live line
    size.ws_row = 24;
    pid_ = ::forkpty(&master_, nullptr, nullptr, &size);
    if (pid_ == 0) exec_lancer(args);
}

PtyProcess::~PtyProcess() {
    if (pid_ > 0 && exit_code_ < 0) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
    }
    if (master_ >= 0) ::close(master_);
}

bool PtyProcess::read_some(int timeout_ms) {
    pollfd p{master_, POLLIN, 0};
    if (::poll(&p, 1, timeout_ms) <= 0) return true;  // nothing yet
    char buffer[4096];
    ssize_t n = ::read(master_, buffer, sizeof buffer);
    if (n <= 0) return false;  // EIO once the process has closed the terminal
    output_.append(buffer, static_cast<std::size_t>(n));
    return true;
}

bool PtyProcess::read_until(const std::function<bool(const std::string&)>& seen, std::chrono::seconds timeout) {
    auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!seen(output_)) {
        if (std::chrono::steady_clock::now() >= deadline || !read_some(100)) return seen(output_);
    }
    return true;
}

void PtyProcess::send(int signal_number) { ::kill(pid_, signal_number); }

int PtyProcess::wait_exit(std::chrono::seconds timeout) {
    read_until([](const std::string&) { return false; }, timeout);  // to the end of the output
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (exit_code_ < 0 && std::chrono::steady_clock::now() < deadline) {
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == pid_)
            exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        else
            ::poll(nullptr, 0, 20);  // polling interval, not synchronisation
    }
    return exit_code_;
}

}  // namespace lancer::test

#include "support/child_process.hpp"

#include <csignal>
#include <fstream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace lancer::test {

ChildProcess::ChildProcess(const std::vector<std::string>& args, const std::string& cwd, const std::string& log_path)
    : log_path_(log_path) {
    pid_ = ::fork();
    if (pid_ == 0) {
        int fd = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(fd, STDERR_FILENO);
        ::dup2(fd, STDOUT_FILENO);
        if (::chdir(cwd.c_str()) != 0) ::_exit(127);
        exec_lancer(args);
    }
}

void exec_lancer(const std::vector<std::string>& args) {
    std::vector<std::string> strings = {LANCER_EXE};
    strings.insert(strings.end(), args.begin(), args.end());
    ::setenv("LANCER_VALIDATION", "1", 1);
    std::vector<char*> argv;
    for (auto& s : strings) argv.push_back(s.data());
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
}

ChildProcess::~ChildProcess() {
    if (pid_ > 0 && exit_code_ < 0) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
    }
}

std::string ChildProcess::log() const {
    std::ifstream in(log_path_);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

bool ChildProcess::wait_until(const std::function<bool()>& ready, std::chrono::seconds timeout) {
    auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
        if (ready()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));  // polling interval, not synchronisation
    }
    return ready();
}

bool ChildProcess::running() {
    if (exit_code_ >= 0) return false;
    int status = 0;
    pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == pid_) {
        exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        return false;
    }
    return true;
}

void ChildProcess::interrupt() { ::kill(pid_, SIGINT); }

int ChildProcess::wait_exit(std::chrono::seconds timeout) {
    wait_until([&] { return !running(); }, timeout);
    return exit_code_;
}

}  // namespace lancer::test

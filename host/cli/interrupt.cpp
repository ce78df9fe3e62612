#include "cli/interrupt.hpp"

#include <csignal>

#include <fcntl.h>
#include <unistd.h>

#include "core/cancel.hpp"

namespace lancer {
namespace {

int g_pipe[2] = {-1, -1};
int g_depth = 0;  // nested Interrupts objects; the outermost owns the handlers and the pipe
struct sigaction g_previous_int, g_previous_term;

void on_signal(int number) {
    request_cancellation(number);
    char byte = 1;
    [[maybe_unused]] ssize_t n = ::write(g_pipe[1], &byte, 1);  // async-signal-safe; a full pipe is fine
}

}  // namespace

Interrupts::Interrupts() {
    if (g_depth++ > 0) return;
    clear_cancellation();
    if (::pipe2(g_pipe, O_CLOEXEC | O_NONBLOCK) != 0) g_pipe[0] = g_pipe[1] = -1;
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // no SA_RESTART: see interrupt.hpp
    ::sigaction(SIGINT, &action, &g_previous_int);
    ::sigaction(SIGTERM, &action, &g_previous_term);
}

Interrupts::~Interrupts() {
    if (--g_depth > 0) return;
    ::sigaction(SIGINT, &g_previous_int, nullptr);
    ::sigaction(SIGTERM, &g_previous_term, nullptr);
    for (int& fd : g_pipe) {
        if (fd >= 0) ::close(fd);
        fd = -1;
    }
}

std::string signal_name(int signal_number) {
    switch (signal_number) {
        case SIGINT: return "SIGINT";
        case SIGTERM: return "SIGTERM";
        default: return "signal " + std::to_string(signal_number);
    }
}

Interrupted::Interrupted(int signal_number, const std::string& what_was_left)
    : std::runtime_error("interrupted by " + signal_name(signal_number) + ": " + what_was_left), signal_(signal_number) {}

bool Interrupts::requested() const { return cancellation_requested(); }
int Interrupts::fd() const { return g_pipe[0]; }
int Interrupts::signal_number() const { return cancellation_signal(); }

}  // namespace lancer

#include "cli/progress.hpp"

#include <cstdio>

#include <unistd.h>

namespace lancer {

ProgressLine::ProgressLine(bool quiet)
    : quiet_(quiet), terminal_(::isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()) {}

void ProgressLine::update(const std::string& label, double fraction) {
    if (quiet_ || !terminal_) return;
    int percent = static_cast<int>(fraction * 100.0);
    if (percent == last_percent_) return;
    last_percent_ = percent;
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, "\r\033[K%s: %3d%%  %.1f s", label.c_str(), percent, elapsed);
    std::fflush(stderr);
    dirty_ = true;
}

void ProgressLine::clear() {
    if (dirty_) std::fprintf(stderr, "\r\033[K");
    dirty_ = false;
    last_percent_ = -1;
}

void ProgressLine::finish(const std::string& message) {
    clear();
    if (!quiet_) std::fprintf(stderr, "%s\n", message.c_str());
}

}  // namespace lancer

#include "cli/progress.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

namespace lancer {
namespace {

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

int terminal_width() {
    winsize size{};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
    return 80;
}

}  // namespace

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

ProgressLine::ProgressLine(bool quiet)
    : quiet_(quiet), terminal_(stderr_is_terminal()), start_(std::chrono::steady_clock::now()) {}

void ProgressLine::update(const std::string& label, double fraction) {
    if (quiet_ || !terminal_) return;
    int percent = static_cast<int>(fraction * 100.0);
    if (percent == last_percent_) return;
    last_percent_ = percent;
    double elapsed = seconds_since(start_);
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

std::string format_phase(const std::string& what, double seconds) {
    return fmt::format("{}  {} s", what, static_cast<long>(std::max(0.0, seconds)));
}

PhaseLine::PhaseLine(bool quiet, const std::string& what)
    : active_(!quiet && stderr_is_terminal()), what_(what), start_(std::chrono::steady_clock::now()), after_(1000) {
    if (!active_) return;
    if (const char* ms = std::getenv("LANCER_PHASE_AFTER_MS")) after_ = std::chrono::milliseconds(std::atol(ms));
    if (after_.count() <= 0) draw();  // at once, before this returns
    ticker_ = std::thread([this] { run(); });
}

void PhaseLine::draw() {
    std::fprintf(stderr, "\r\033[K%s", format_phase(what_, seconds_since(start_)).c_str());
    std::fflush(stderr);
    drawn_ = true;
}

PhaseLine::~PhaseLine() { clear(); }

void PhaseLine::run() {
    std::unique_lock lock(mutex_);
    auto next = drawn_ ? start_ + std::chrono::seconds(1) : start_ + after_;
    while (!wake_.wait_until(lock, next, [this] { return done_; })) {
        draw();
        next += std::chrono::seconds(1);
    }
    if (drawn_) std::fprintf(stderr, "\r\033[K");
}

void PhaseLine::clear() {
    if (!ticker_.joinable()) return;
    {
        std::lock_guard lock(mutex_);
        done_ = true;
    }
    wake_.notify_one();
    ticker_.join();
}

std::string format_clock(double seconds) {
    long s = std::lround(std::max(0.0, seconds));
    if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
    return fmt::format("{}:{:02}", s / 60, s % 60);
}

double estimate_remaining(double elapsed, int done, double fraction, int total) {
    double work = done + fraction;
    if (done < 1 && fraction < 0.05) return -1.0;  // the first percent of the first frame says little
    return elapsed / work * (total - work);
}

std::string format_frame_status(const FrameStatus& s, int max_width) {
    std::string head = fmt::format("frame {}/{} ", s.index, s.count);
    std::string tail = fmt::format("  {:3d}%  {} elapsed, ETA {}", static_cast<int>(s.fraction * 100.0),
                                   format_clock(s.elapsed), s.eta < 0.0 ? "--:--" : format_clock(s.eta));
    // Never reach the last column: a terminal that wraps there garbles the rewritten line.
    int room = max_width - 1 - static_cast<int>(head.size() + tail.size());
    std::string path = s.path;
    if (room < static_cast<int>(path.size())) path = room >= 4 ? "..." + path.substr(path.size() - (room - 3)) : "";
    std::string line = head + path + tail;
    if (static_cast<int>(line.size()) > max_width - 1) line.resize(std::max(0, max_width - 1));
    return line;
}

FrameProgress::FrameProgress(bool quiet, int count) : quiet_(quiet), terminal_(stderr_is_terminal()), count_(count) {}

void FrameProgress::begin(int frame, const std::string& path) {
    if (!started_) start_ = std::chrono::steady_clock::now();
    started_ = true;
    frame_ = frame;
    path_ = path;
    last_percent_ = -1;
    draw(0.0);
}

void FrameProgress::update(double fraction) {
    int percent = static_cast<int>(fraction * 100.0);
    // Redraw when the percentage moves, and at least twice a second so the clocks tick.
    if (percent == last_percent_ && seconds_since(last_draw_) < 0.5) return;
    draw(fraction);
}

void FrameProgress::draw(double fraction) {
    if (quiet_ || !terminal_) return;
    last_percent_ = static_cast<int>(fraction * 100.0);
    last_draw_ = std::chrono::steady_clock::now();
    FrameStatus s;
    s.index = done_ + 1;
    s.count = count_;
    s.path = path_;
    s.fraction = fraction;
    s.elapsed = seconds_since(start_);
    s.eta = estimate_remaining(s.elapsed, done_, fraction, count_);
    std::fprintf(stderr, "\r\033[K%s", format_frame_status(s, terminal_width()).c_str());
    std::fflush(stderr);
    dirty_ = true;
}

void FrameProgress::end(double seconds) {
    ++done_;
    if (quiet_ || terminal_) return;
    std::fprintf(stderr, "%s: frame %d (%d/%d), %.3f s\n", path_.c_str(), frame_, done_, count_, seconds);
    std::fflush(stderr);
}

void FrameProgress::message(const std::string& line) {
    if (quiet_) return;
    clear();
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
}

void FrameProgress::status(const std::string& line) {
    if (quiet_ || !terminal_) return;
    std::fprintf(stderr, "\r\033[K%s", line.c_str());
    std::fflush(stderr);
    dirty_ = true;
}

void FrameProgress::clear() {
    if (dirty_) std::fprintf(stderr, "\r\033[K");
    dirty_ = false;
}

}  // namespace lancer

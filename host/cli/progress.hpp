#pragma once
// Progress on stderr. On a terminal: one live, rewritten line. Elsewhere (logs, CI): a still
// render prints only its summary, and an animation one plain line per finished frame, so logs
// never fill with carriage returns.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace lancer {

// Seconds from t until now, on the clock progress is timed with.
double seconds_since(std::chrono::steady_clock::time_point t);

class ProgressLine {
public:
    explicit ProgressLine(bool quiet);
    // fraction in [0, 1]; `label` prefixes the line ("seed.png").
    void update(const std::string& label, double fraction);
    // Clears the live line and prints `message` on its own line (unless quiet).
    void finish(const std::string& message);
    void clear();

private:
    bool quiet_;
    bool terminal_;
    bool dirty_ = false;
    int last_percent_ = -1;
    std::chrono::steady_clock::time_point start_;
};

// What lancer is doing before its first progress (reading a large scene, building its BVH,
// compiling shaders), for as long as that takes: on a terminal, after `after` of it, a live line
// "reading big.toml  3 s", redrawn each second by a thread of its own until the phase changes or
// this ends (then cleared); elsewhere, and when quiet, nothing. LANCER_PHASE_AFTER_MS sets
// `after` (1 s by default; tests use 0, which draws at once).
class PhaseLine {
public:
    PhaseLine(bool quiet, const std::string& what);
    ~PhaseLine();
    void clear();  // ends it early: the line goes and no other is drawn

private:
    void run();
    void draw();

    bool active_;
    std::string what_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::milliseconds after_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false, drawn_ = false;
    std::thread ticker_;
};

// "reading big.toml  12 s": the phase and its whole seconds so far.
std::string format_phase(const std::string& what, double seconds);

// The live line of an animation, as a pure function so it can be tested:
// "frame 3/10 orbit_012.png  45%  0:12 elapsed, ETA 1:05", shortened (the path first) to fit
// `max_width` columns.
struct FrameStatus {
    int index = 1;          // 1-based, among the frames this run renders
    int count = 1;          // frames this run renders
    std::string path;       // of the frame being rendered
    double fraction = 0.0;  // of the current frame
    double elapsed = 0.0;   // seconds since the first frame started
    double eta = -1.0;      // seconds left, negative when not yet known
};
std::string format_frame_status(const FrameStatus& status, int max_width);

// "0:07", "12:34", "1:02:03".
std::string format_clock(double seconds);

// Seconds left when `done` of `total` frames are finished and `fraction` of the next, after
// `elapsed` seconds: the mean time per frame so far times the frames left. -1 before anything
// is finished, when no estimate can be made.
double estimate_remaining(double elapsed, int done, double fraction, int total);

class FrameProgress {
public:
    FrameProgress(bool quiet, int count);
    void begin(int frame, const std::string& path);
    void update(double fraction);
    // The frame is written: elsewhere than on a terminal this prints its line.
    void end(double seconds);
    // A line of its own, e.g. the summary (clears the live line first).
    void message(const std::string& line);
    // Clears the live line (before an error message).
    void clear();
    // What is going on now, as the live line on a terminal (elsewhere nothing): "encoding ...".
    void status(const std::string& line);

private:
    void draw(double fraction);

    bool quiet_;
    bool terminal_;
    int count_;
    int done_ = 0;
    int frame_ = 0;
    std::string path_;
    bool started_ = false;
    bool dirty_ = false;
    int last_percent_ = -1;
    std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace lancer

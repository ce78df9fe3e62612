#pragma once
// Progress on stderr: a live, rewritten line on a terminal; nothing but the summary otherwise
// (logs and CI get one clean line per render instead of a wall of carriage returns).
#include <chrono>
#include <string>

namespace lancer {

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

}  // namespace lancer

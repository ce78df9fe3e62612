#pragma once
// A virtual X server (Xvfb) for the viewer's tests, and the X tools that drive and photograph
// windows on it: xdotool (keys, mouse) and xwd (screenshots). Xvfb reports its display number
// through -displayfd once it accepts connections, so nothing waits a fixed time.
#include <string>

#include <sys/types.h>

#include "image/image.hpp"

namespace lancer::test {

class XServer {
public:
    // Starts Xvfb with one 24-bit screen. Throws std::runtime_error with a clear message when
    // Xvfb is missing (setup.sh installs it: Debian package xvfb) or does not come up in time.
    XServer();
    ~XServer();  // stops it
    XServer(const XServer&) = delete;
    XServer& operator=(const XServer&) = delete;

    const std::string& display() const { return display_; }  // ":N"

    // Runs an X client (e.g. "xdotool key Right") on this display; returns its exit code and
    // puts its stdout in `out` when given.
    int run(const std::string& command, std::string* out = nullptr) const;

    // The id of the first viewable window whose class is `window_class` (a lancer window's class
    // is "lancer"), waiting up to `timeout_s` for it. Empty when there is none.
    std::string find_window(const std::string& window_class, int timeout_s = 30) const;

    // A screenshot of a window's contents (xwd), as 8-bit RGB.
    Rgb8Image screenshot(const std::string& window_id) const;

private:
    pid_t pid_ = -1;
    std::string display_;
    std::string log_;  // Xvfb's messages
};

// Reads an XWD file (xwd's format: a big-endian header, a colour map, then the pixels) of a
// 24- or 32-bit TrueColor ZPixmap. Throws std::runtime_error for anything else.
Rgb8Image read_xwd(const std::string& path);

// True when `program` is on PATH.
bool have_program(const std::string& program);

}  // namespace lancer::test

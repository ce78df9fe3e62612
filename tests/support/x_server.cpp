#include "support/x_server.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <thread>
#include <vector>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include "support/test_support.hpp"

namespace lancer::test {

bool have_program(const std::string& program) {
    return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

XServer::XServer() {
    if (!have_program("Xvfb"))
        throw std::runtime_error("Xvfb is not installed: the viewer's tests need it (Debian package xvfb; ./setup.sh installs it)");
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("pipe failed");
    log_ = output_dir() + "/xvfb-" + std::to_string(::getpid()) + ".log";
    pid_ = ::fork();
    if (pid_ == 0) {
        ::close(fds[0]);
        std::string fd = std::to_string(fds[1]);
        FILE* f = std::freopen(log_.c_str(), "w", stderr);
        (void)f;
        ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1024x768x24", "-nolisten", "tcp", "-noreset",
                 static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ::close(fds[1]);
    // Xvfb writes "N\n" when it is ready; a bounded wait for it.
    std::string number;
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (std::chrono::steady_clock::now() < deadline) {
        pollfd p{fds[0], POLLIN, 0};
        if (::poll(&p, 1, 200) <= 0) continue;
        char c;
        ssize_t n = ::read(fds[0], &c, 1);
        if (n <= 0) break;  // Xvfb exited
        if (c == '\n') break;
        number += c;
    }
    ::close(fds[0]);
    if (number.empty()) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
        pid_ = -1;
        throw std::runtime_error("Xvfb did not start (see " + log_ + ")");
    }
    display_ = ":" + number;
}

XServer::~XServer() {
    if (pid_ > 0) {
        ::kill(pid_, SIGTERM);
        ::waitpid(pid_, nullptr, 0);
        std::remove(log_.c_str());  // only kept when Xvfb did not start
    }
}

int XServer::run(const std::string& command, std::string* out) const {
    std::string file = output_dir() + "/xclient-" + std::to_string(::getpid()) + ".out";
    int status = std::system(("DISPLAY=" + display_ + " " + command + " >" + file + " 2>&1").c_str());
    if (out) {
        std::ifstream in(file);
        out->assign(std::istreambuf_iterator<char>(in), {});
    }
    std::remove(file.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string XServer::find_window(const std::string& window_class, int timeout_s) const {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
    do {
        std::string out;
        if (run("xdotool search --onlyvisible --class " + window_class, &out) == 0) {
            std::string id = out.substr(0, out.find('\n'));
            if (!id.empty()) return id;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));  // polling interval
    } while (std::chrono::steady_clock::now() < deadline);
    return "";
}

Rgb8Image XServer::screenshot(const std::string& window_id) const {
    std::string file = output_dir() + "/shot-" + std::to_string(::getpid()) + ".xwd";
    std::string out;
    if (run("xwd -silent -id " + window_id + " -out " + file, &out) != 0) throw std::runtime_error("xwd failed: " + out);
    Rgb8Image image = read_xwd(file);
    std::remove(file.c_str());
    return image;
}

namespace {

std::uint32_t big_endian(const std::uint8_t* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | p[3];
}

int shift_of(std::uint32_t mask) {
    int s = 0;
    while (mask && !(mask & 1u)) {
        mask >>= 1;
        ++s;
    }
    return s;
}

}  // namespace

Rgb8Image read_xwd(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<std::uint8_t> data((std::istreambuf_iterator<char>(in)), {});
    if (data.size() < 100) throw std::runtime_error(path + ": not an XWD file");
    auto field = [&](int i) { return big_endian(&data[std::size_t(i) * 4]); };
    const std::uint32_t header_size = field(0), format = field(2), width = field(4), height = field(5),
                        byte_order = field(7), bits_per_pixel = field(11), bytes_per_line = field(12),
                        red_mask = field(14), green_mask = field(15), blue_mask = field(16), ncolors = field(19);
    if (format != 2 || (bits_per_pixel != 32 && bits_per_pixel != 24))
        throw std::runtime_error(path + ": only 24/32-bit ZPixmap XWD files are supported");
    std::size_t offset = header_size + std::size_t(ncolors) * 12;
    if (data.size() < offset + std::size_t(bytes_per_line) * height) throw std::runtime_error(path + ": truncated");
    Rgb8Image image{int(width), int(height), std::vector<std::uint8_t>(std::size_t(width) * height * 3)};
    const int bytes = int(bits_per_pixel / 8);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::uint8_t* p = &data[offset + std::size_t(y) * bytes_per_line + std::size_t(x) * bytes];
            std::uint32_t v = 0;
            for (int b = 0; b < bytes; ++b)  // byte_order 0: least significant byte first
                v |= std::uint32_t(p[b]) << (8 * (byte_order == 0 ? b : bytes - 1 - b));
            std::uint8_t* o = &image.bytes[(std::size_t(y) * width + x) * 3];
            o[0] = std::uint8_t((v & red_mask) >> shift_of(red_mask));
            o[1] = std::uint8_t((v & green_mask) >> shift_of(green_mask));
            o[2] = std::uint8_t((v & blue_mask) >> shift_of(blue_mask));
        }
    return image;
}

}  // namespace lancer::test

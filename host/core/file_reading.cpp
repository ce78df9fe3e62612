#include "core/file_reading.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/cancel.hpp"
#include "core/error.hpp"

namespace lancer {

InputFile::InputFile(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) throw UserError("it is a directory");
    for (;;) {
        fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd_ >= 0) return;
        if (errno != EINTR) throw UserError(std::strerror(errno));
        throw_if_cancelled();
    }
}

InputFile::~InputFile() { ::close(fd_); }

bool InputFile::read_some(std::string& out, std::size_t bytes) {
    const std::size_t at = out.size();
    out.resize(at + bytes);
    for (;;) {
        ssize_t n = ::read(fd_, out.data() + at, bytes);
        if (n >= 0) {
            out.resize(at + static_cast<std::size_t>(n));
            return n > 0;
        }
        if (errno != EINTR) {
            out.resize(at);
            throw UserError(std::strerror(errno));
        }
        throw_if_cancelled();
    }
}

FileText read_file(const std::string& path, std::size_t limit) {
    InputFile file(path);
    FileText result;
    while (file.read_some(result.text, 1 << 16)) {
        if (result.text.size() > limit) {
            result.complete = false;
            break;
        }
    }
    return result;
}

std::optional<std::string> read_regular_file_nonblocking(const std::string& path, std::size_t max_bytes, Links links) {
    const int flags = O_RDONLY | O_NONBLOCK | O_CLOEXEC | (links == Links::refuse ? O_NOFOLLOW : 0);
    int fd;
    do fd = ::open(path.c_str(), flags);
    while (fd < 0 && errno == EINTR);
    if (fd < 0) return std::nullopt;  // missing, unreadable, a link (ELOOP), ...
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size < 0 ||
        static_cast<std::uintmax_t>(st.st_size) > max_bytes)
        return std::nullopt;
    // The file may grow while it is read: read to its end, but never past the bound.
    std::string text;
    text.reserve(static_cast<std::size_t>(st.st_size));
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0) {
            if (errno == EINTR) continue;
            return std::nullopt;
        }
        if (n == 0) break;
        if (static_cast<std::size_t>(n) > max_bytes - text.size()) return std::nullopt;
        text.append(buffer, static_cast<std::size_t>(n));
    }
    return text;
}

}  // namespace lancer

#include "core/file_reading.hpp"

#include <cerrno>
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

}  // namespace lancer

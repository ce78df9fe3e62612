#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.hpp"
#include "core/temporary_name.hpp"
#include "image/image.hpp"
#include "image/image_file.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace lancer {
namespace {

std::string os_error(const std::string& what, const std::string& path) {
    return what + " '" + path + "': " + std::strerror(errno);
}

// Writes all of `data` to fd, retrying short writes.
bool write_all(int fd, const unsigned char* data, std::size_t size) {
    while (size > 0) {
        ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace

void write_png(const std::string& path, const Rgb8Image& image) {
    int length = 0;
    std::unique_ptr<unsigned char, decltype(&free)> png(
        stbi_write_png_to_mem(image.bytes.data(), image.width * 3, image.width, image.height, 3, &length), &free);
    if (!png) throw UserError("cannot encode PNG for '" + path + "'");
    write_file_atomically(path, png.get(), static_cast<std::size_t>(length));
}

void write_file_atomically(const std::string& path, const void* data, std::size_t size) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw UserError("cannot write '" + path + "': it is a directory");
    std::string temp = temporary_template(path);
    int fd = ::mkstemp(temp.data());
    if (fd < 0) throw UserError(os_error("cannot write", path));
    bool ok = write_all(fd, static_cast<const unsigned char*>(data), size) && ::fsync(fd) == 0;
    int saved_errno = errno;
    ok = (::close(fd) == 0) && ok;
    if (!ok || ::chmod(temp.c_str(), 0644) != 0 || ::rename(temp.c_str(), path.c_str()) != 0) {
        if (!ok) errno = saved_errno;
        std::string message = os_error("cannot write", path);
        ::unlink(temp.c_str());
        throw UserError(message);
    }
}

Rgb8Image read_png(const std::string& path) {
    try {
        ImageFile file = read_image_file(path, {kMaxReadSide, kMaxReadPixels});
        return Rgb8Image{file.size.width, file.size.height, decode_image(file, 3)};
    } catch (const UserError& e) {
        throw UserError("cannot read PNG '" + path + "': " + e.what());
    }
}

}  // namespace lancer

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>

#include <fcntl.h>
#include <libdeflate.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.hpp"
#include "core/temporary_name.hpp"
#include "image/image.hpp"
#include "image/image_file.hpp"

namespace lancer {
namespace {
// stb_image_write's own deflate made a 1280x720 picture's PNG cost 60 ms, a noticeable part of
// a render of a second; with libdeflate (level 6) and Paeth rows it takes 19 ms, and the files
// come out 15-30% smaller (docs/performance.md).
unsigned char* deflate_for_png(unsigned char* data, int size, int* out_size, int /*stb_quality*/);
}  // namespace
}  // namespace lancer

#define STBIW_ZLIB_COMPRESS lancer::deflate_for_png
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace lancer {
namespace {

unsigned char* deflate_for_png(unsigned char* data, int size, int* out_size, int /*stb_quality*/) {
    std::unique_ptr<libdeflate_compressor, decltype(&libdeflate_free_compressor)> compressor(
        libdeflate_alloc_compressor(6), &libdeflate_free_compressor);
    if (!compressor) return nullptr;
    std::size_t bound = libdeflate_zlib_compress_bound(compressor.get(), static_cast<std::size_t>(size));
    auto* out = static_cast<unsigned char*>(STBIW_MALLOC(bound));  // stb frees it with STBIW_FREE
    if (!out) return nullptr;
    std::size_t written = libdeflate_zlib_compress(compressor.get(), data, static_cast<std::size_t>(size), out, bound);
    if (written == 0 || written > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
        STBIW_FREE(out);
        return nullptr;
    }
    *out_size = static_cast<int>(written);
    return out;
}

// Every row Paeth-filtered: stb's per-row choice (each row filtered five ways) made the encoding
// with libdeflate 1.3-1.7x as long for files 0-5% smaller. Set once, before any thread writes a
// PNG.
[[maybe_unused]] const bool paeth_rows = (stbi_write_force_png_filter = 4, true);

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

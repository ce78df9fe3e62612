#include "image/texture_image.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include <stb/stb_image.h>

#include "core/error.hpp"

namespace lancer {
namespace {

using File = std::unique_ptr<std::FILE, decltype(&std::fclose)>;

// Opens the file for reading, or says in a few words why it cannot be.
File open_image(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw UserError("it is a directory");
    File file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) throw UserError(std::strerror(errno));
    return file;
}

}  // namespace

ImageSize probe_texture_image(const std::string& path) {
    File file = open_image(path);
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_file(file.get(), &w, &h, &channels)) throw UserError("not a PNG, JPEG or BMP image");
    return {w, h};
}

TextureImage read_texture_image(const std::string& path) {
    ImageSize size = probe_texture_image(path);
    File file = open_image(path);
    int w = 0, h = 0, channels = 0;
    std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> data(stbi_load_from_file(file.get(), &w, &h, &channels, 4),
                                                              &stbi_image_free);
    if (!data) throw UserError(std::string("corrupt or truncated image (") + stbi_failure_reason() + ")");
    if (w != size.width || h != size.height) throw UserError("the image's size changed while it was read");
    TextureImage image{w, h, {}};
    image.rgba.assign(data.get(), data.get() + std::size_t(w) * std::size_t(h) * 4);
    return image;
}

}  // namespace lancer

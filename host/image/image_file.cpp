#include "image/image_file.hpp"

#include <algorithm>
#include <climits>
#include <memory>

#include <fmt/format.h>
#include <stb/stb_image.h>

#include "core/error.hpp"
#include "core/file_reading.hpp"
#include "image/decode_budget.hpp"

namespace lancer {
namespace {

constexpr std::size_t kHeaderBytes = 64 * 1024;   // enough for any PNG, JPEG or BMP header stb needs
constexpr std::uint64_t kSlack = 16ull << 20;      // ancillary data (colour profiles, text, EXIF)
constexpr std::uint64_t kDecodeSlack = 1ull << 20;  // stb's own tables and small buffers

std::uint32_t be32(std::string_view s, std::size_t at) {
    auto b = [&](std::size_t i) { return std::uint32_t(static_cast<unsigned char>(s[at + i])); };
    return (b(0) << 24) | (b(1) << 16) | (b(2) << 8) | b(3);
}

bool is_png(std::string_view s) { return s.size() >= 33 && s.substr(0, 8) == "\x89PNG\r\n\x1a\n" && s.substr(12, 4) == "IHDR"; }

// Bytes of the filtered scanlines (a filter byte per row) of a PNG, all passes of an interlaced one.
std::uint64_t png_raw_bytes(std::uint64_t w, std::uint64_t h, int bits_per_pixel, bool interlaced) {
    auto rows = [&](std::uint64_t pw, std::uint64_t ph) { return pw && ph ? ph * (1 + (pw * bits_per_pixel + 7) / 8) : 0; };
    if (!interlaced) return rows(w, h);
    // Adam7: each pass takes every dx-th pixel from x0 of every dy-th row from y0.
    static const std::uint64_t passes[7][4] = {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4},
                                               {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}};
    std::uint64_t total = 0;
    for (const auto& [x0, y0, dx, dy] : passes)
        total += rows(w > x0 ? (w - x0 + dx - 1) / dx : 0, h > y0 ? (h - y0 + dy - 1) / dy : 0);
    return total;
}

int png_bits_per_pixel(int color_type, int bit_depth) {
    const int channels = color_type == 0 ? 1 : color_type == 2 ? 3 : color_type == 3 ? 1 : color_type == 4 ? 2 : 4;
    return channels * bit_depth;
}

// The sum of a PNG's IDAT chunk lengths in `bytes` (as far as the file goes).
std::uint64_t png_idat_bytes(std::string_view bytes) {
    std::uint64_t total = 0;
    for (std::size_t at = 8; at + 8 <= bytes.size();) {
        std::uint64_t length = be32(bytes, at);
        std::string_view type = bytes.substr(at + 4, 4);
        if (type == "IDAT") total += length;
        if (type == "IEND") break;
        at += 12 + length;
    }
    return total;
}

// The most bytes a file of this header can sensibly hold: PNG by deflate's bound on the size in
// its header, the other formats (stored or DCT-coded pixels) by 8 bytes a pixel.
std::uint64_t max_file_bytes(std::string_view header, const ImageSize& size) {
    if (std::uint64_t png = png_max_compressed_bytes(header)) return png + kSlack;
    return std::uint64_t(size.width) * std::uint64_t(size.height) * 8 + kSlack;
}

}  // namespace

std::uint64_t png_max_compressed_bytes(std::string_view header) {
    if (!is_png(header)) return 0;
    const std::uint64_t w = be32(header, 16), h = be32(header, 20);
    const int bit_depth = static_cast<unsigned char>(header[24]), color_type = static_cast<unsigned char>(header[25]);
    const bool interlaced = header[28] != 0;
    const std::uint64_t raw = png_raw_bytes(w, h, png_bits_per_pixel(color_type, bit_depth), interlaced);
    // Deflate stores incompressible data with 5 bytes per 64 KiB block; an encoder that chose
    // poor codes could spend up to 15 bits a byte. Twice the raw size, plus room for a zlib header
    // and empty blocks, is beyond anything an encoder makes.
    return 2 * raw + 64 * 1024;
}

ImageFile read_image_file(const std::string& path, const ImageLimits& limits) {
    InputFile input(path);
    ImageFile file;
    while (file.bytes.size() < kHeaderBytes && input.read_some(file.bytes, kHeaderBytes - file.bytes.size())) {
    }
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(file.bytes.data()), static_cast<int>(file.bytes.size()),
                               &w, &h, &channels))
        throw UserError("not a PNG, JPEG or BMP image");
    file.size = {w, h};
    if (w > limits.max_side || h > limits.max_side)
        throw UserError(fmt::format("it is {}x{} pixels; the limit is {} on each side", w, h, limits.max_side));
    if (static_cast<long long>(w) * h > limits.max_pixels)
        throw UserError(fmt::format("it is {}x{} pixels; the limit is {} pixels", w, h, limits.max_pixels));

    const std::uint64_t cap = max_file_bytes(file.bytes, file.size);
    while (input.read_some(file.bytes, 1 << 20)) {
        if (file.bytes.size() > cap)
            throw UserError(fmt::format("the file holds more than {} bytes, more than a {}x{} image can need "
                                        "(a decompression bomb, or not an image)",
                                        cap, w, h));
    }
    if (file.bytes.size() > static_cast<std::size_t>(INT32_MAX))  // stb takes an int
        throw UserError(fmt::format("the file holds {} bytes; lancer reads images of up to 2 GiB", file.bytes.size()));
    if (std::uint64_t need = png_max_compressed_bytes(file.bytes)) {
        std::uint64_t idat = png_idat_bytes(file.bytes);
        if (idat > need)
            throw UserError(fmt::format("its compressed image data is {} bytes, more than a {}x{} PNG can need ({} bytes): "
                                        "a decompression bomb, or a corrupt file",
                                        idat, w, h, need));
    }
    return file;
}

std::vector<std::uint8_t> decode_image(const ImageFile& file, int channels) {
    const std::uint64_t pixels = std::uint64_t(file.size.width) * std::uint64_t(file.size.height);
    // What stb needs for an image of the header's size: a copy of the compressed data, the
    // inflated scanlines, and the pixels at up to 16 bits a channel with a conversion or two.
    const std::uint64_t budget =
        2 * file.bytes.size() + 2 * png_max_compressed_bytes(file.bytes) + 4 * pixels * 8 + kDecodeSlack;
    DecodeBudget cap(static_cast<std::size_t>(budget));
    int w = 0, h = 0, n = 0;
    std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> data(
        stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(file.bytes.data()), static_cast<int>(file.bytes.size()),
                              &w, &h, &n, channels),
        &stbi_image_free);
    if (!data) {
        if (cap.exceeded())
            throw UserError(fmt::format("its data decodes to more than a {}x{} image holds (a decompression bomb, or a "
                                        "corrupt file): stopped at {} MiB",
                                        file.size.width, file.size.height, budget >> 20));
        throw UserError(std::string("corrupt or truncated image (") + stbi_failure_reason() + ")");
    }
    if (w != file.size.width || h != file.size.height) throw UserError("the image's size differs from its header's");
    return std::vector<std::uint8_t>(data.get(), data.get() + pixels * std::size_t(channels));
}

}  // namespace lancer

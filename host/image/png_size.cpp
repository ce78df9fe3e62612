#include "image/png_size.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>

namespace lancer {

std::optional<PngSize> read_png_size(const std::string& path) {
    // Signature (8 bytes), then the IHDR chunk: length (4), "IHDR" (4), width and height (4 each, big-endian).
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char header[24];
    std::ifstream in(path, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return std::nullopt;
    if (std::memcmp(header, kSignature, 8) != 0 || std::memcmp(header + 12, "IHDR", 4) != 0) return std::nullopt;
    auto be32 = [&](int at) {
        return (std::uint32_t(header[at]) << 24) | (std::uint32_t(header[at + 1]) << 16) |
               (std::uint32_t(header[at + 2]) << 8) | std::uint32_t(header[at + 3]);
    };
    std::uint32_t w = be32(16), h = be32(20);
    if (w == 0 || h == 0 || w > 0x7fffffff || h > 0x7fffffff) return std::nullopt;
    return PngSize{static_cast<int>(w), static_cast<int>(h)};
}

}  // namespace lancer

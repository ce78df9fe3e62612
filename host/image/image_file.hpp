#pragma once
// Image files as untrusted input (textures, the PNGs `lancer diff` compares, finished frames):
// read whole, sized from the header, and decoded only within bounds worked out from that size
// before anything large is allocated. A file that claims to be small but holds much more (a
// decompression bomb: a "1x1" PNG with megabytes of compressed data) fails at once, and the
// decoder's memory is capped whatever the data says.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lancer {

struct ImageSize {
    int width = 0;
    int height = 0;
};

struct ImageLimits {
    int max_side = 0;            // pixels on each side
    long long max_pixels = 0;    // width x height
};

// The whole file, read once (a FIFO too), stopped as soon as it is larger than an image within
// `limits` can be (PNG: its compressed data is bounded by the size in its header). Checks the
// header's size against `limits`. Throws UserError saying why the file cannot be used: it does
// not exist, is a directory, is not a PNG, JPEG or BMP image, or is too large.
struct ImageFile {
    std::string bytes;
    ImageSize size;
};
ImageFile read_image_file(const std::string& path, const ImageLimits& limits);

// Decodes to `channels` (3: RGB, 4: RGBA) 8-bit channels per pixel, row 0 at the top.
// Throws UserError for corrupt or truncated data, and for data that decodes to more than the
// header's size (the decoder's memory is capped accordingly).
std::vector<std::uint8_t> decode_image(const ImageFile& file, int channels);

// How many bytes of compressed data a PNG of this header can need at most: deflate's worst case
// for the filtered scanlines (every pass of an interlaced image counted), generously. 0 for a
// header that is not a PNG's.
std::uint64_t png_max_compressed_bytes(std::string_view header);

}  // namespace lancer

#pragma once
// Images used as textures: read with stb_image (PNG, JPEG, BMP), kept as the file's 8-bit sRGB
// texels. Decoding to linear light is the renderers' job (each does it its own way).
#include <cstdint>
#include <string>
#include <vector>

namespace lancer {

struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // 4 bytes a texel, sRGB-encoded, row 0 at the top of the image
};

struct ImageSize {
    int width = 0;
    int height = 0;
};

// The size from the file's header, without decoding it (so limits are checked before anything
// is allocated). Throws UserError whose message says why the file cannot be used: it does not
// exist, is a directory, is not readable, or is not a PNG, JPEG or BMP image.
ImageSize probe_texture_image(const std::string& path);

// The whole image as RGBA8 (grey and palette images expanded, 16-bit channels reduced to 8,
// alpha 255 where the file has none). Throws UserError as probe_texture_image does, and for
// corrupt or truncated data.
TextureImage read_texture_image(const std::string& path);

}  // namespace lancer

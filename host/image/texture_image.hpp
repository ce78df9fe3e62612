#pragma once
// Images used as textures: read with stb_image (PNG, JPEG, BMP), kept as the file's 8-bit sRGB
// texels. Decoding to linear light is the renderers' job (each does it its own way).
#include <cstdint>
#include <string>
#include <vector>

#include "image/image_file.hpp"

namespace lancer {

struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // 4 bytes a texel, sRGB-encoded, row 0 at the top of the image
};

// The whole image of a file read by read_image_file() as RGBA8 (grey and palette images
// expanded, 16-bit channels reduced to 8, alpha 255 where the file has none). Throws UserError
// for corrupt or truncated data, and for data that decodes to more than the header says.
TextureImage decode_texture_image(const ImageFile& file);

}  // namespace lancer

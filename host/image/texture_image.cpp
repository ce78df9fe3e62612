#include "image/texture_image.hpp"

namespace lancer {

TextureImage decode_texture_image(const ImageFile& file) {
    return TextureImage{file.size.width, file.size.height, decode_image(file, 4)};
}

}  // namespace lancer

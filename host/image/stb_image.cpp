// The one stb_image implementation in the program: PNG (scene diffs, tests), PNG, JPEG and BMP
// (textures). Other formats stay out, so a stray file is never mistaken for an image.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#include <stb/stb_image.h>

// The one stb_image implementation in the program: PNG (scene diffs, tests), PNG, JPEG and BMP
// (textures). Other formats stay out, so a stray file is never mistaken for an image. Its
// allocations count against the decoding thread's DecodeBudget (image/image_file.cpp sets one
// from the image's header), so that no file can make it allocate more than its size needs.
#include "image/decode_budget.hpp"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#define STBI_MALLOC(bytes) lancer::budget_malloc(bytes)
#define STBI_REALLOC(block, bytes) lancer::budget_realloc(block, bytes)
#define STBI_FREE(block) lancer::budget_free(block)
#include <stb/stb_image.h>

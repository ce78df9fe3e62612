#pragma once
// The size of a PNG from its header, without decoding it: how an animation tells a finished
// frame (a PNG of the requested size) from anything else at its path.
#include <optional>
#include <string>

namespace lancer {

struct PngSize {
    int width = 0;
    int height = 0;
};

// nullopt when the file does not exist, cannot be read or is not a PNG.
std::optional<PngSize> read_png_size(const std::string& path);

}  // namespace lancer

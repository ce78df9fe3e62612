#include "image/diff.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "core/error.hpp"

namespace lancer {

ImageDiff compare_images(const Rgb8Image& a, const Rgb8Image& b, int threshold) {
    if (a.width != b.width || a.height != b.height)
        throw UserError("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
                        std::to_string(b.width) + "x" + std::to_string(b.height));
    ImageDiff d;
    d.threshold = threshold;
    double squared = 0.0;
    std::size_t over = 0;
    std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
    for (std::size_t i = 0; i < pixels; ++i) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            int delta = std::abs(int(a.bytes[i * 3 + c]) - int(b.bytes[i * 3 + c]));
            squared += double(delta) * delta;
            worst = std::max(worst, delta);
        }
        d.max_abs = std::max(d.max_abs, worst);
        if (worst > threshold) ++over;
    }
    double mse = squared / (3.0 * pixels);
    d.psnr_db = mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);
    d.fraction_over = double(over) / pixels;
    return d;
}

Rgb8Image difference_image(const Rgb8Image& a, const Rgb8Image& b) {
    Rgb8Image out{a.width, a.height, std::vector<std::uint8_t>(a.bytes.size())};
    for (std::size_t i = 0; i < a.bytes.size() && i < b.bytes.size(); ++i)
        out.bytes[i] = static_cast<std::uint8_t>(std::min(255, 8 * std::abs(int(a.bytes[i]) - int(b.bytes[i]))));
    return out;
}

}  // namespace lancer

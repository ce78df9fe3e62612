#pragma once
// Comparing two 8-bit images: the metric the image tests and `lancer diff` use.
#include <string>

#include "image/image.hpp"

namespace lancer {

struct ImageDiff {
    double psnr_db = 0.0;            // over all RGB channels; +inf when identical
    double fraction_over = 0.0;      // share of pixels with any channel off by more than `threshold`
    int max_abs = 0;                 // largest channel difference
    int threshold = 0;
};

// Throws UserError when the sizes differ.
ImageDiff compare_images(const Rgb8Image& a, const Rgb8Image& b, int threshold);

// |a - b| per channel, amplified x8 so that 1-level differences are visible.
Rgb8Image difference_image(const Rgb8Image& a, const Rgb8Image& b);

}  // namespace lancer

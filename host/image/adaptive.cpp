#include "image/adaptive.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/vec3.hpp>

namespace lancer {

double color_difference(const glm::vec4& a, const glm::vec4& b) {
    double d = 0.0;
    for (int c = 0; c < 3; ++c) d += std::abs(int(encode_srgb8(a[c])) - int(encode_srgb8(b[c]))) / 255.0;
    return d;
}

std::vector<std::uint32_t> pixels_to_refine(const FloatImage& one_ray, double threshold) {
    const int w = one_ray.width, h = one_ray.height;
    std::vector<char> refine(std::size_t(w) * h, threshold <= 0.0);
    if (threshold > 0.0) {
        // Each pair of neighbours once: to the right and below.
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * w + x;
                if (x + 1 < w && color_difference(one_ray.pixels[i], one_ray.pixels[i + 1]) > threshold)
                    refine[i] = refine[i + 1] = 1;
                if (y + 1 < h && color_difference(one_ray.pixels[i], one_ray.pixels[i + w]) > threshold)
                    refine[i] = refine[i + w] = 1;
            }
        }
    }
    std::vector<std::uint32_t> pixels;
    for (std::size_t i = 0; i < refine.size(); ++i)
        if (refine[i]) pixels.push_back(static_cast<std::uint32_t>(i));
    return pixels;
}

void merge_refined(FloatImage& one_ray, const std::vector<std::uint32_t>& pixels, const std::vector<glm::vec4>& refined) {
    if (pixels.size() != refined.size()) throw std::logic_error("merge_refined: one colour per refined pixel");
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        glm::vec4& p = one_ray.pixels[pixels[i]];
        p = glm::vec4(glm::vec3(refined[i]), p.a + refined[i].a);
    }
}

}  // namespace lancer

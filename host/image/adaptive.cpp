#include "image/adaptive.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace lancer {

namespace {

std::atomic<std::size_t> g_pixels_to_refine_calls{0};

int code_distance(float a, float b) { return std::abs(int(encode_srgb8(a)) - int(encode_srgb8(b))); }

}  // namespace

double code_difference(int dr, int dg, int db) {
    double d = 0.0;
    d += dr / 255.0;
    d += dg / 255.0;
    d += db / 255.0;
    return d;
}

double color_difference(const glm::vec4& a, const glm::vec4& b) {
    return code_difference(code_distance(a.r, b.r), code_distance(a.g, b.g), code_distance(a.b, b.b));
}

std::size_t pixels_to_refine_calls() { return g_pixels_to_refine_calls.load(); }

double sample_spread(const glm::vec3& lo, const glm::vec3& hi) {
    return color_difference(glm::vec4(lo, 0.0f), glm::vec4(hi, 0.0f));
}

int max_aa_depth(int samples) { return std::max(1, samples - 1); }

std::vector<int> aa_grid_levels(int samples, int depth) {
    if (samples <= 1) return {1};
    depth = std::clamp(depth, 1, max_aa_depth(samples));
    std::vector<int> grids{1};
    for (int k = 1; k <= depth; ++k) {
        // Evenly in log(grid), but each larger than the last and leaving room for the ones after.
        const int ideal = int(std::lround(std::pow(double(samples), double(k) / depth)));
        grids.push_back(std::clamp(ideal, grids.back() + 1, samples - (depth - k)));
    }
    return grids;
}

std::vector<std::uint32_t> pixels_to_refine(const FloatImage& image, double threshold,
                                            const std::vector<char>& candidates) {
    ++g_pixels_to_refine_calls;
    const int w = image.width, h = image.height;
    auto candidate = [&](std::size_t i) { return candidates.empty() || candidates[i]; };
    std::vector<char> refine(std::size_t(w) * h, 0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            if (threshold <= 0.0) {
                refine[i] = candidate(i);
                continue;
            }
            // Each pair of neighbours once: to the right and below.
            for (std::size_t j : {x + 1 < w ? i + 1 : i, y + 1 < h ? i + w : i}) {
                if (j == i || !(candidate(i) || candidate(j))) continue;
                if (color_difference(image.pixels[i], image.pixels[j]) > threshold) {
                    refine[i] |= candidate(i);
                    refine[j] |= candidate(j);
                }
            }
        }
    }
    std::vector<std::uint32_t> pixels;
    for (std::size_t i = 0; i < refine.size(); ++i)
        if (refine[i]) pixels.push_back(static_cast<std::uint32_t>(i));
    return pixels;
}

}  // namespace lancer

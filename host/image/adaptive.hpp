#pragma once
// Adaptive anti-aliasing (POV-Ray's +AM1), the part both renderers share: which pixels of a
// one-ray-per-pixel picture get the full N x N grid, and how the two pictures are combined.
#include <cstdint>
#include <vector>

#include "image/image.hpp"

namespace lancer {

// POV-Ray's colour difference, |r1 - r2| + |g1 - g2| + |b1 - b2| (0..3), over the colours as
// the PNG holds them (sRGB-encoded, 0..1), not the linear ones: in linear terms an edge in the
// dark (a checker line in shadow) differs by a few hundredths and would never be refined.
double color_difference(const glm::vec4& a, const glm::vec4& b);

// The pixels (y * width + x, ascending) of `one_ray` that differ from one of their four
// neighbours by more than `threshold`: both pixels of such a pair, as POV-Ray refines both.
// A threshold of 0 selects every pixel, so that T = 0 gives the full grid everywhere.
std::vector<std::uint32_t> pixels_to_refine(const FloatImage& one_ray, double threshold);

// Writes the refined pixels' colours (refined[i] for pixel pixels[i]) into `one_ray`; a pixel's
// ray count becomes its first ray's plus its grid's, so the counts say what was traced.
void merge_refined(FloatImage& one_ray, const std::vector<std::uint32_t>& pixels, const std::vector<glm::vec4>& refined);

}  // namespace lancer

#pragma once
// Adaptive anti-aliasing, the part both renderers share: the grids of the refinements and which
// pixels of a picture go on to the next grid. The order of the passes, and how their pictures
// are combined, is render/adaptive_render.hpp's.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "image/image.hpp"

namespace lancer {

// POV-Ray's colour difference, |r1 - r2| + |g1 - g2| + |b1 - b2| (0..3), over the colours as
// the PNG holds them (sRGB-encoded, 0..1), not the linear ones: in linear terms an edge in the
// dark (a checker line in shadow) differs by a few hundredths and would never be refined.
double color_difference(const glm::vec4& a, const glm::vec4& b);
// The same from the absolute differences of the three 8-bit codes, operation for operation (the
// GPU's selection decides from tables of it: image/difference_tables.hpp).
double code_difference(int dr, int dg, int db);

// How far a pixel's samples spread: POV-Ray's difference between the per-channel smallest and
// largest of their linear colours `lo` and `hi`, sRGB-encoded as color_difference() measures.
// It is at least the largest difference between two of the samples, and equals it when one
// sample is the darkest in every channel and another the brightest (the usual case: an edge).
double sample_spread(const glm::vec3& lo, const glm::vec3& hi);

// The grid sizes a pixel goes through, 1 x 1 first and `samples` x `samples` last: depth + 1 of
// them (fewer when `samples` has too few grids between), spread evenly in log(grid), e.g.
// samples 3: depth 1 -> 1, 3; depth 2 -> 1, 2, 3. samples 8, depth 3 -> 1, 2, 4, 8.
std::vector<int> aa_grid_levels(int samples, int depth);

// The most refinements `samples` allows: one grid size per refinement, each larger than the last.
int max_aa_depth(int samples);

// The pixels (y * width + x, ascending) among `candidates` (all when empty) that differ from one
// of their four neighbours by more than `threshold`: both pixels of such a pair when both are
// candidates, as POV-Ray refines both. A threshold of 0 selects every candidate, so that T = 0
// ends with the full grid everywhere.
std::vector<std::uint32_t> pixels_to_refine(const FloatImage& image, double threshold,
                                            const std::vector<char>& candidates = {});

// How many times this process has called pixels_to_refine() (for tests: the GPU chooses on the
// device and must not call it).
std::size_t pixels_to_refine_calls();

}  // namespace lancer

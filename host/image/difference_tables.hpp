#pragma once
// image/adaptive.hpp's colour difference as tables, so that a GPU, which has neither the host's
// powf nor double, decides exactly as color_difference() does with exact comparisons and integer
// arithmetic alone (shaders/refine_select.comp).
#include <array>
#include <cstdint>
#include <vector>

namespace lancer {

// For each 8-bit sRGB code k (1..255), the least float that encode_srgb8() maps to k or above
// (entry 0 is 0). encode_srgb8 is non-decreasing, so the code of a float f is the largest k
// with f >= entry k, and 0 when there is none (negative, NaN).
const std::array<float, 256>& srgb8_level_starts();

// For each pair of absolute red and green code differences (dr, dg), at dr * 256 + dg: the
// least blue difference db for which color_difference() > threshold, computed with the very
// double operations it does; 256 when none. A pixel pair then differs by more than the threshold
// exactly when db >= the entry (the sum grows with db, as rounding is monotonic).
std::vector<std::uint32_t> blue_difference_floors(double threshold);

}  // namespace lancer

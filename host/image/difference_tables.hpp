#pragma once
// image/adaptive.hpp's colour difference as tables, so that a GPU, which has neither the host's
// powf nor double, decides exactly as color_difference() does with exact comparisons and integer
// arithmetic alone (shaders/refine_select.comp); the sRGB codes' own table,
// srgb8_level_starts(), is image/image.hpp's.
#include <array>
#include <cstdint>
#include <vector>

namespace lancer {

// For each pair of absolute red and green code differences (dr, dg), at dr * 256 + dg: the
// least blue difference db for which color_difference() > threshold, computed with the very
// double operations it does; 256 when none. A pixel pair then differs by more than the threshold
// exactly when db >= the entry (the sum grows with db, as rounding is monotonic).
std::vector<std::uint32_t> blue_difference_floors(double threshold);

}  // namespace lancer

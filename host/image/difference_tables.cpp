#include "image/difference_tables.hpp"

#include "image/adaptive.hpp"
#include "image/image.hpp"

namespace lancer {

std::vector<std::uint32_t> blue_difference_floors(double threshold) {
    std::vector<std::uint32_t> floors(256 * 256);
    for (int dr = 0; dr < 256; ++dr)
        for (int dg = 0; dg < 256; ++dg) {
            int lo = -1, hi = 256;  // sum(lo) <= threshold (or lo = -1), sum(hi) > threshold (or hi = 256)
            while (hi - lo > 1) {
                const int mid = (lo + hi) / 2;
                (code_difference(dr, dg, mid) > threshold ? hi : lo) = mid;
            }
            floors[std::size_t(dr) * 256 + dg] = static_cast<std::uint32_t>(hi);
        }
    return floors;
}

}  // namespace lancer

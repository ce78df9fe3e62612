#include "image/difference_tables.hpp"

#include <bit>
#include <cmath>

#include "image/adaptive.hpp"
#include "image/image.hpp"

namespace lancer {
namespace {

std::array<float, 256> make_level_starts() {
    std::array<float, 256> starts{};
    // Non-negative floats order as their bit patterns do: bisect the patterns of [0, 1].
    for (int k = 1; k < 256; ++k) {
        std::uint32_t lo = 0, hi = std::bit_cast<std::uint32_t>(1.0f);  // encode(lo) < k <= encode(hi)
        while (hi - lo > 1) {
            const std::uint32_t mid = lo + (hi - lo) / 2;
            (encode_srgb8(std::bit_cast<float>(mid)) >= k ? hi : lo) = mid;
        }
        starts[k] = std::bit_cast<float>(hi);
    }
    return starts;
}

}  // namespace

const std::array<float, 256>& srgb8_level_starts() {
    static const std::array<float, 256> starts = make_level_starts();
    return starts;
}

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

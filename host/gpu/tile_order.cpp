#include "gpu/tile_order.hpp"

#include <cmath>
#include <numeric>

namespace lancer::gpu {

std::uint32_t spread_group_stride(std::uint32_t groups) {
    if (groups < 3 || groups > 65535) return 1;
    // The golden section's Weyl sequence leaves the most even gaps in any run of its terms.
    const double golden_section = 0.5 * (std::sqrt(5.0) - 1.0);
    auto stride = static_cast<std::uint32_t>(std::lround(golden_section * groups));
    while (std::gcd(stride, groups) != 1) ++stride;
    return stride;
}

}  // namespace lancer::gpu

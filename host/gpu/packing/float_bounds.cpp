#include "gpu/packing/float_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace lancer::gpu {

void pack_box(const Aabb& box, vec4& lo, vec4& hi) {
    double pad = 1e-6 * std::max({1.0, glm::length(box.lo), glm::length(box.hi)});
    lo = vec4(round_down(box.lo.x - pad), round_down(box.lo.y - pad), round_down(box.lo.z - pad), 0.0f);
    hi = vec4(round_up(box.hi.x + pad), round_up(box.hi.y + pad), round_up(box.hi.z + pad), 0.0f);
}

}  // namespace lancer::gpu

#pragma once
// The order in which a dispatch's workgroups take the tiles of a band (BandParams::group_stride).
#include <cstdint>

namespace lancer::gpu {

// A stride for a dispatch of `groups` workgroups: workgroup g renders tile (g * stride) mod
// groups, a permutation (the stride is coprime with `groups`). Near the golden section of
// `groups`, every run of consecutive workgroups holds tiles spread evenly over the band, so a
// driver that hands each thread one run (driver_quirks.hpp) gives each about the same work,
// whatever its number of threads. 1 (tiles in order) where `groups` times the stride could
// overflow the shader's 32-bit product.
std::uint32_t spread_group_stride(std::uint32_t groups);

}  // namespace lancer::gpu

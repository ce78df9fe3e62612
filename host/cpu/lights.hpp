#pragma once
// The CPU reference's lights: the points a shading point sees a light from (the light itself,
// or the n x n samples of an area light) and how much of its colour arrives (spot cone,
// distance fall-off). Written independently of shaders/lights.glsl; the sample positions come
// from the same integer hash, so both backends place area light samples alike.
#include <cstdint>

#include "scene/scene.hpp"

namespace lancer::cpu {

// PCG's 32-bit output permutation (exact, wrapping unsigned arithmetic).
std::uint32_t hash_u32(std::uint32_t v);

// The seed of one camera sample: pixel (x, y), grid sample k = j * N + i.
std::uint32_t camera_sample_seed(std::uint32_t x, std::uint32_t y, std::uint32_t k);

// Number of point samples of a light: n x n for an area light, else 1.
int light_sample_count(const Light& light);

// Sample s of light number `index` (see docs/scene-format.md, "[[light]]"); `seed` identifies the
// camera sample and the shading point.
dvec3 light_sample_position(const Light& light, std::uint32_t index, int s, std::uint32_t seed);

// The light's colour arriving at p from its sample q, one of `count` samples.
dvec3 light_intensity(const Light& light, const dvec3& q, const dvec3& p, int count);

}  // namespace lancer::cpu

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

// The top 24 bits of a hash as a number in [0, 1), exactly the float the shader computes.
double unit_interval(std::uint32_t h);

// The seed of one camera sample: pixel (x, y), grid sample k = j * N + i.
std::uint32_t camera_sample_seed(std::uint32_t x, std::uint32_t y, std::uint32_t k);

// Photon mapping renders one camera sample per pixel per pass: pass k takes grid sample
// j = k mod N^2 (docs/scene-format.md). The first N^2 passes sample the cells' centres with the
// seeds of a plain render; each later round r = k / N^2 a hashed place in the cell, with the
// seed h(camera_sample_seed ^ h(r)). (dx, dy): the position within the pixel, in [0, 1).
struct PassSample {
    double dx, dy;
    std::uint32_t seed;
};
PassSample photon_pass_sample(std::uint32_t x, std::uint32_t y, std::uint32_t n, std::uint32_t pass);

// Number of point samples of a light: n x n for an area light, else 1.
int light_sample_count(const Light& light);

// Sample s of light number `index` (see docs/scene-format.md, "[[light]]"); `seed` identifies the
// camera sample and the shading point.
dvec3 light_sample_position(const Light& light, std::uint32_t index, int s, std::uint32_t seed);

// A spot light's factor for the unit direction from its apex (docs/scene-format.md): 0 outside
// its cone, cos^tightness times the smooth edge inside.
double spot_factor(const Light& light, const dvec3& from_light);

// The light's colour arriving at p from its sample q, one of `count` samples.
dvec3 light_intensity(const Light& light, const dvec3& q, const dvec3& p, int count);

}  // namespace lancer::cpu

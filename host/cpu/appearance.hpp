#pragma once
// What a material looks like at a hit, for the CPU reference: its pigment (colour or checker,
// times texture, times pattern) and its shading normal (tilted by a bump). The shader's twin is
// shaders/appearance.glsl.
#include "cpu/tracer.hpp"

namespace lancer::cpu {

struct Appearance {
    dvec3 pigment;
    dvec3 normal;  // unit, the geometric normal unless a bump tilts it
};

// n: the unit geometric normal, already facing the viewer.
Appearance appearance_at(const Material& m, const Hit& hit, const dvec3& p, const dvec3& n);

// The mirror direction of d about the shading normal, turned back above the geometric surface
// if a bump tilted it below (it would otherwise start inside the object).
dvec3 bounce_direction(const dvec3& d, const dvec3& shading_normal, const dvec3& geometric_normal);

}  // namespace lancer::cpu

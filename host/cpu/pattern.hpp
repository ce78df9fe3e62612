#pragma once
// Procedural patterns for the CPU reference: the scalar function f of a pattern (noise,
// turbulence, marble, wood) with its gradient, the colour ramp, and bump mapping. The rules are
// in docs/scene-format.md ("Patterns"); the shader's twin is shaders/pattern.glsl.
#include "cpu/noise.hpp"
#include "scene/scene.hpp"

namespace lancer::cpu {

// f at pattern-space point q, with its gradient in pattern space.
NoiseSample pattern_value(const Pattern& pattern, const dvec3& q);

// The ramp's colour at t: the first colour below the first stop, the last above the last, linear
// in between.
dvec3 ramp_color(const std::vector<ColorStop>& ramp, double t);

// The colour of a colour pattern at point p of its object's coordinates.
dvec3 pattern_color(const Pattern& pattern, const dvec3& p);

// The unit world normal n (facing the viewer) tilted by the bump's pattern at point p of its
// object's coordinates, which `object_to_world` (the linear part of its placement) turns.
dvec3 bumped_normal(const Bump& bump, const dvec3& p, const dvec3& n, const glm::dmat3& object_to_world = glm::dmat3(1.0));

}  // namespace lancer::cpu

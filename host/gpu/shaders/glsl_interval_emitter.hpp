#pragma once
// GLSL that encloses an implicit surface's f along a piece of a ray: interval arithmetic with
// forward-mode derivatives (the GPU's twin of Dual<Interval>), calling shaders/interval.glsl.
//
//   void NAME(vec3 o, vec3 d, vec2 s, out vec2 f, out vec2 df)
//
// f contains f(o + t d) and df contains its derivative in t, for every t in [s.x, s.y]
// (within interval.glsl's rounding margins). Constants are rounded outward to float; integer
// powers are chains of products, so no loop runs (lavapipe counts loop iterations).
#include <string>

#include "surface/expr/program.hpp"

namespace lancer::gpu {

// `program` has one output, an expression in x, y, z (variables 0, 1, 2).
std::string emit_glsl_interval(const surface::Program& program, const std::string& function_name);

//   dvec2 NAME(dvec3 o, dvec3 d, dvec2 s)
//
// The same enclosure of f(o + t d) for t in [s.x, s.y], without the derivative and in double
// (interval.glsl's dvec2 overloads): used at a point, where float's rounding cannot tell f from 0.
std::string emit_glsl_interval_at_a_point(const surface::Program& program, const std::string& function_name);

}  // namespace lancer::gpu

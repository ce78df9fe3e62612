#pragma once
// GLSL for expression surfaces: functions that compute an expression and its exact derivatives
// by forward-mode differentiation, one SSA temporary per operation. A parametric surface:
//
//   void NAME(vec2 uv, out vec3 P, out vec3 Pu, out vec3 Pv)
//
// with P = S(uv), Pu = dS/du, Pv = dS/dv in the surface's own coordinates (no transform). An
// implicit surface f(x, y, z), in its own coordinates:
//
//   float NAME(vec3 p, vec3 d, out float df)        f(p), and df its derivative along d
//   vec3 NAME_gradient(vec3 p)                       the gradient of f at p
//   void NAME_interval(vec3 o, vec3 d, vec2 s, out vec2 f, out vec2 df)
//                                                    enclosures of f(o + s d) and of its derivative
//                                                    in s for s in [s.x, s.y] (shaders/interval.glsl)
//
// No user text reaches the output: names come from lancer's own function table, numbers are
// printed by the emitter. The derivative rules are those of Dual<T> (dual.hpp).
#include <string>

#include "surface/expr/expr.hpp"

namespace lancer::gpu {

// function_name must be a GLSL identifier (letters, digits, '_'; not starting with a digit or
// "gl_"); std::invalid_argument otherwise.
std::string emit_glsl_surface(const surface::Expr& x, const surface::Expr& y, const surface::Expr& z, const std::string& function_name);
// `in_double_at_a_point` adds NAME_at_a_point, f's enclosure at a point in double
// (emit_glsl_interval_at_a_point), for devices with shaderFloat64.
std::string emit_glsl_implicit(const surface::Expr& f, const std::string& function_name, bool in_double_at_a_point = false);

// A double as a GLSL float literal that reads back as the nearest float: "2.0", "0.100000001",
// "1e-05", "(-1.5)"; out-of-range values become +-infinity.
std::string glsl_float(double value);

}  // namespace lancer::gpu

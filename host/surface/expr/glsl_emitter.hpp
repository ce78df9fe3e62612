#pragma once
// GLSL for a parametric surface: a function that computes S(u, v) and its exact partial
// derivatives by forward-mode differentiation, one SSA temporary per operation:
//
//   void NAME(vec2 uv, out vec3 P, out vec3 Pu, out vec3 Pv)
//
// with P = S(uv), Pu = dS/du, Pv = dS/dv in the surface's own coordinates (no transform).
// No user text reaches the output: names come from lancer's own function table, numbers are
// printed by the emitter. The derivative rules are those of Dual<T> (dual.hpp).
#include <string>

#include "surface/expr/expr.hpp"

namespace lancer::surface {

// function_name must be a GLSL identifier (letters, digits, '_'; not starting with a digit or
// "gl_"); std::invalid_argument otherwise.
std::string emit_glsl_surface(const Expr& x, const Expr& y, const Expr& z, const std::string& function_name);

// A double as a GLSL float literal that reads back as the nearest float: "2.0", "0.100000001",
// "1e-05", "(-1.5)"; out-of-range values become +-infinity.
std::string glsl_float(double value);

}  // namespace lancer::surface

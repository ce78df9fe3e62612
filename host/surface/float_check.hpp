#pragma once
// The GPU evaluates a parametric surface in float; the CPU reference and everything the loader
// proves (the domain check, the cells' boxes) work in double. Where float arithmetic cannot
// follow double (a constant beyond float's range, an intermediate value that overflows, large
// terms that cancel), the GPU would draw another surface than the reference, silently. These
// checks refuse such a surface at load, at the expression and column where float gives out, and
// measure how far float strays on the surfaces they accept, so that the cells' boxes can hold
// the surface the GPU evaluates.
#include <string>

#include "surface/expr/expr.hpp"
#include "surface/expr/program.hpp"
#include "surface/implicit_surface.hpp"
#include "surface/parametric_surface.hpp"

namespace lancer::surface {

// Float's range, as the checks use it: finite magnitudes up to kFloatMax, nonzero ones from
// kFloatMinNormal (a GPU may flush smaller ones to zero).
constexpr double kFloatMax = 3.4028234663852886e38;
constexpr double kFloatMinNormal = 1.1754943508222875e-38;

// A surface the GPU cannot evaluate in float: at node column `column` of expression
// `expression` (0: x, 1: y, 2: z).
class FloatEvaluationError : public ExprError {
public:
    FloatEvaluationError(const std::string& message, int column, int expression)
        : ExprError(message, column), expression(expression) {}
    int expression;
};

// Every constant that is left after constants are folded (in double, as the GLSL emitter folds
// them) must be a float: ExprError at the first one that is not, naming it and float's range.
void check_float_constants(const Expr& expr);

// Evaluates the surface (points and partial derivatives) as the GPU does (GpuFloat) and in
// double, on a grid of (grid + 1)^2 points of the domain. Throws FloatEvaluationError where an operation's float result
// is not finite but double's is, and where the two points are further apart than 1e-3 of the
// surface's extent. Returns the largest distance between the two points, in the surface's own
// frame (before its transform).
double check_float_evaluation(const Program& program, const ParametricSurface& surface, int grid = 64);

// The same for an implicit surface, whose f and gradient the GPU evaluates in float to find and
// shade its zeros: on a grid of (grid + 1)^3 points of the box, FloatEvaluationError (expression
// 0) where an operation's float result is not finite but double's is, and where float's f strays
// from double's by more than 1e-3 of f's range over the box (a zero found by float's f then lies
// that far off, relative to the box). Returns the largest difference in f.
double check_float_evaluation(const ImplicitSurface& surface, int grid = 16);

}  // namespace lancer::surface

#pragma once
// A surface given by its equation f(x, y, z) = 0, clipped to a box of its own coordinates and
// placed in the world by an affine transform. When f is a polynomial its expansion is kept too:
// the CPU reference then intersects rays with it exactly (companion matrix), any other f by
// interval Newton.
#include <array>
#include <optional>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "surface/expr/expr.hpp"
#include "surface/expr/program.hpp"
#include "surface/polynomial.hpp"

namespace lancer::surface {

using glm::dvec3;

struct ImplicitSurface {
    Expr f;                                  // in x, y, z (variables 0, 1, 2)
    Program program;                         // f compiled: one output
    std::optional<Polynomial3> polynomial;   // the expansion, when f is a polynomial
    dvec3 box_lo{-1.0}, box_hi{1.0};         // the box f = 0 is clipped to, in the surface's coordinates
    // The part of the box where the surface can be (shrink_to_surface, when loaded; unset: all of
    // it): where the GPU searches. The box itself still maps textures.
    std::optional<std::array<dvec3, 2>> search_box;
    glm::dmat4 to_world{1.0};                // affine: surface coordinates -> world
    glm::dmat4 to_local{1.0};                // its inverse

    int degree() const { return polynomial ? polynomial->degree() : 0; }  // 0: not a polynomial
    void place(const glm::dmat4& m);          // sets to_world and to_local
};

// f and its gradient at a point of the surface's own coordinates (forward-mode derivatives).
struct ImplicitPoint {
    double f;
    dvec3 gradient;
};
ImplicitPoint evaluate_implicit(const ImplicitSurface& s, const dvec3& local);

// The unit normal at a world point of the surface: its gradient, carried to world space by the
// inverse transpose of the transform. Where the gradient vanishes or is not finite (a singular
// point: a cone's apex, a double point, a self-intersection) it is the gradient a growing step
// away along the box's diagonal, as on the GPU; failing that, +z. Never NaN, always unit length.
dvec3 implicit_normal(const ImplicitSurface& s, const dvec3& world);

// Texture (u, v) at a point of the surface's own coordinates: x and y across the box, in [0, 1].
glm::dvec2 implicit_texture_uv(const ImplicitSurface& s, const dvec3& local);

// Whether interval arithmetic proves, within `budget` sub-boxes, that f has no zero in the box
// (f > 0 or f < 0 wherever it is defined there): the surface is empty. False when it cannot tell.
bool proved_without_zero(const ImplicitSurface& s, int budget = 4096);
bool proved_without_zero(const ImplicitSurface& s, const dvec3& lo, const dvec3& hi, int budget);

// Whether interval arithmetic proves, within `budget` pieces, that f > 0 all over the box's six
// faces, so that the surface closes the region f < 0 in the box (CSG takes it as a solid's
// inside): none where proved, else a point (the surface's coordinates) where it could not be.
std::optional<dvec3> not_proved_positive_on_faces(const ImplicitSurface& s, int budget = 20000);

// The box [lo, hi] shrunk, face by face, past slabs of it that interval arithmetic proves hold no
// zero of f, to within 1/64 of its size (and a margin of that much again): the part of the
// surface's box where the surface can be. A unit sphere given a box of 10^6 gets one of about its
// own size, whose scale the GPU's float search can resolve.
void shrink_to_surface(const ImplicitSurface& s, dvec3& lo, dvec3& hi);

// Where f's zero set is not a surface that both renderers can find the same way, what it is
// instead, for the loader's error: f is 0 over one of the box's faces (the surface lies on the
// box's boundary, where clipping decides whether it is seen) or throughout a region of the box (a
// solid of zeros has no surface in it to find). Found by sampling f with interval arithmetic on a
// grid of the box and of each face (0 where the rounding cannot tell f from 0); nothing otherwise.
std::optional<std::string> degenerate_zero_set(const ImplicitSurface& s);

// The surface's box in world space (the transformed box's eight corners, boxed).
void implicit_world_bounds(const ImplicitSurface& s, dvec3& lo, dvec3& hi);

}  // namespace lancer::surface

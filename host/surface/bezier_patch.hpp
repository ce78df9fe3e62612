#pragma once
// Bicubic tensor-product Bezier patches, polynomial or rational: the exact geometry that the CPU
// reference intersects by elimination and the GPU by Bezier clipping. Everything here works in
// homogeneous coordinates (w P, w), so rational patches are split, evaluated and bounded exactly
// like polynomial ones; a patch whose weights are all 1 stays polynomial through every operation.
#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <utility>

namespace lancer::surface {

using glm::dvec3;

// Control points row-major: points[4 * i + j] is P_ij, i along u, j along v.
// Rational patches need every weight > 0 (then the convex hull property holds).
struct BezierPatch {
    std::array<dvec3, 16> points{};
    std::array<double, 16> weights{1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
};

inline const dvec3& control_point(const BezierPatch& p, int i, int j) { return p.points[4 * i + j]; }

// True unless every weight is exactly 1.
bool is_rational(const BezierPatch& p);

// S(u, v).
dvec3 evaluate(const BezierPatch& p, double u, double v);

// S and its first and second partial derivatives (quotient rule for rational patches).
struct SurfaceJet {
    dvec3 s, su, sv, suu, suv, svv;
};
SurfaceJet evaluate_jet(const BezierPatch& p, double u, double v);

// The piece of p over [u0, u1] x [v0, v1] as a patch of its own (reparametrised to [0, 1]^2),
// by blossoming in homogeneous coordinates: no approximation, only rounding. u0 > u1 reverses
// the direction. Pieces that share a parameter line share that boundary bit for bit.
BezierPatch sub_patch(const BezierPatch& p, double u0, double u1, double v0, double v1);
std::pair<BezierPatch, BezierPatch> split_u(const BezierPatch& p, double u);  // [0,u], [u,1]
std::pair<BezierPatch, BezierPatch> split_v(const BezierPatch& p, double v);

// The box of the control points, which contains the whole patch (convex hull property).
struct PatchBounds {
    dvec3 min{0.0};
    dvec3 max{0.0};
};
PatchBounds bounds(const BezierPatch& p);

// The patch mapped by an affine transform (bottom row 0 0 0 1; anything else throws
// std::invalid_argument). Exact: affine maps commute with the Bezier combination, weights included.
BezierPatch transformed(const BezierPatch& p, const glm::dmat4& affine);

// The unit normal, in the direction of Su x Sv. Where that vanishes (collapsed edges such as the
// teapot's lid apex and bottom centre, or other degenerate points) it is the limit of the normal
// approached from inside the domain. Always a finite unit vector.
dvec3 unit_normal(const BezierPatch& p, double u, double v);

}  // namespace lancer::surface

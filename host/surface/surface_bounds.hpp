#pragma once
// Guaranteed bounds of a surface over a parameter box, and the affine map applied to them: the
// boxes of the GPU's cells. (The CPU reference bounds its own boxes, so that a mistake here
// cannot hide in both renderers at once.)
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "surface/dual.hpp"
#include "surface/expr/program.hpp"
#include "surface/interval.hpp"

namespace lancer::surface {

using glm::dvec3;

struct IntervalVec3 {
    Interval x, y, z;
    Interval& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    const Interval& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    bool is_empty() const { return x.is_empty() || y.is_empty() || z.is_empty(); }
};

// Bounds of S and of its partials over the box, in the program's (the surface's own) frame.
struct BoxBounds {
    IntervalVec3 S;       // contains S(u, v) for every (u, v) in the box where S is defined
    IntervalVec3 Su, Sv;  // contain the partials (meaningful only when `smooth`)
    bool smooth = false;  // every operation is defined and differentiable on the whole box
};

// Bounds of the second partials over the box (infinite where they cannot be bounded).
struct SecondPartials {
    IntervalVec3 Suu, Suv, Svv;
};
SecondPartials bound_second_partials(const Program& program, const Interval& u, const Interval& v);

// The natural interval extension, narrowed by the mean-value form S(c) + [J](X - c) where it
// applies (smooth boxes); the result is the intersection of the two, so never looser than
// either. `program` has three outputs x, y, z.
BoxBounds bound_surface(const Program& program, const Interval& u, const Interval& v);

// M * p for an affine M, as intervals (outward rounded).
IntervalVec3 transform_point(const glm::dmat4& m, const IntervalVec3& p);
// The linear part of M applied to a vector.
IntervalVec3 transform_vector(const glm::dmat4& m, const IntervalVec3& p);

// The world box of S over the box, given its local bounds: M applied to the mean-value form term
// by term (tighter than boxing the local box and transforming it), intersected with the
// transformed local box.
IntervalVec3 world_bounds(const BoxBounds& local, const Program& program, const glm::dmat4& to_world,
                          const Interval& u, const Interval& v);

}  // namespace lancer::surface

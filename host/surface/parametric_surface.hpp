#pragma once
// A surface given by expressions x(u, v), y(u, v), z(u, v) over the rectangle
// [u0, u1] x [v0, v1], placed in the world by an affine transform.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "surface/expr/expr.hpp"
#include "surface/lazy_slot.hpp"

namespace lancer::surface {

using glm::dvec3;

struct ParametricSurface {
    Expr x, y, z;
    double u0 = 0.0, u1 = 1.0, v0 = 0.0, v1 = 1.0;
    glm::dmat4 to_world{1.0};  // affine (translate, rotate, scale), applied to S(u, v)

    // Data a renderer derives from the fields above on first use (the CPU reference keeps its
    // box tree here). Do not change the fields once a surface has been rendered; copy it instead
    // (a copy starts with an empty slot).
    LazySlot derived;
};

// World-space point and partial derivatives.
struct SurfacePoint {
    dvec3 P, Pu, Pv;
};

SurfacePoint evaluate_surface(const ParametricSurface& surface, double u, double v);

// The unit normal normalize(Pu x Pv) in world space. Where the parametrisation degenerates
// (a pole, a collapsed edge, Pu parallel to Pv) it is the limit of the normals at points
// approaching (u, v) from the inside of the domain; never NaN, always unit length.
dvec3 surface_normal(const ParametricSurface& surface, double u, double v);

}  // namespace lancer::surface

#include "scene/placement.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "scene/animation.hpp"
#include "scene/shape_bounds.hpp"

namespace lancer {

dvec3 Placement::world_normal(const dvec3& n) const {
    return glm::normalize(glm::transpose(glm::dmat3(to_object)) * n);
}

double similarity_scale(const glm::dmat4& m) {
    const glm::dmat3 l(m);
    if (!(glm::determinant(l) > 0.0)) return 0.0;
    const glm::dmat3 g = glm::transpose(l) * l;  // s^2 I for s times a rotation
    const double s2 = (g[0][0] + g[1][1] + g[2][2]) / 3.0;
    constexpr double kTolerance = 1e-12;  // a rotation by angles in degrees is orthogonal to ~1e-16
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (std::abs(g[c][r] - (c == r ? s2 : 0.0)) > kTolerance * s2) return 0.0;
    return std::sqrt(s2);
}

namespace {

dvec3 apply(const glm::dmat4& m, const dvec3& p) { return dvec3(m * glm::dvec4(p, 1.0)); }

// Applies m to the shape where its family keeps its form (and its texture mapping) under m:
// true, or false where the shape must keep its own coordinates.
struct Absorber {
    const glm::dmat4& m;
    const double s = similarity_scale(m);  // 0: not a similarity
    const glm::dmat3 rotation = s > 0.0 ? glm::dmat3(m) / s : glm::dmat3(1.0);

    bool operator()(Sphere& sphere) const {
        if (s == 0.0) return false;  // an ellipsoid
        sphere.center = apply(m, sphere.center);
        sphere.radius *= s;
        sphere.orientation = rotation * sphere.orientation;
        return true;
    }
    bool operator()(Plane& plane) const {
        if (s == 0.0) return false;  // a plane still, but its texture's axes would shear
        plane.point = apply(m, plane.point);
        plane.normal = glm::normalize(rotation * plane.normal);
        // Texture (u, v) are distances in the object's units: the axes shrink by s.
        plane.u_axis = rotation * plane.u_axis / s;
        plane.v_axis = rotation * plane.v_axis / s;
        return true;
    }
    bool operator()(Rectangle& r) const {  // a parallelogram under any affine map, (a, b) kept
        r.edge_u = glm::dmat3(m) * r.edge_u;
        r.edge_v = glm::dmat3(m) * r.edge_v;
        r.corner = apply(m, r.corner);
        return true;
    }
    bool operator()(Box& b) const {  // axis-aligned while the map only scales each axis up
        const glm::dmat3 l(m);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r)
                if ((c == r) ? !(l[c][r] > 0.0) : l[c][r] != 0.0) return false;
        b.min = apply(m, b.min);
        b.max = apply(m, b.max);
        return true;
    }
    bool operator()(Disc& d) const {
        if (s == 0.0) return false;  // an ellipse
        d.center = apply(m, d.center);
        d.normal = glm::normalize(rotation * d.normal);
        d.u_axis = glm::normalize(rotation * d.u_axis);
        d.v_axis = glm::normalize(rotation * d.v_axis);
        d.radius *= s;
        d.hole_radius *= s;
        return true;
    }
    bool operator()(Cone& c) const {
        if (s == 0.0) return false;  // elliptic
        c.base = apply(m, c.base);
        c.cap = apply(m, c.cap);
        c.base_radius *= s;
        c.cap_radius *= s;
        c.u_axis = glm::normalize(rotation * c.u_axis);
        c.v_axis = glm::normalize(rotation * c.v_axis);
        return true;
    }
    bool operator()(Torus& o) const {
        if (s == 0.0) return false;  // stretched: no longer a torus of revolution
        o.center = apply(m, o.center);
        o.axis = glm::normalize(rotation * o.axis);
        o.major_radius *= s;
        o.minor_radius *= s;
        o.u_axis = glm::normalize(rotation * o.u_axis);
        o.v_axis = glm::normalize(rotation * o.v_axis);
        return true;
    }
    bool operator()(Blob& o) const {  // the fields' shape is kept by a similarity, not by a stretch
        if (s == 0.0) return false;
        for (BlobComponent& k : o.components) {
            k.a = apply(m, k.a);
            k.b = apply(m, k.b);
            k.radius *= s;
        }
        prepare_blob(o);
        return true;
    }
    bool operator()(Csg&) const { return true; }  // its reader placed each leaf
    // Their readers applied the transform (exactly: control points, the surfaces' own maps).
    bool operator()(BezierSurface&) const { return true; }
    bool operator()(ParametricObject&) const { return true; }
    bool operator()(ImplicitObject&) const { return true; }
    bool operator()(Mesh&) const { return false; }  // shared by its placements: never copied
    bool operator()(Sor&) const { return false; }   // about its own y axis, always
    bool operator()(Prism&) const { return false; } // along its own y axis, always
    bool operator()(Lathe&) const { return false; }  // about its own y axis, always
    bool operator()(Superellipsoid&) const { return false; }  // in [-1, 1]^3 of its own coordinates, always
    bool operator()(SphereSet&) const { return false; }
};

}  // namespace

void place(Object& o, const glm::dmat4& m) {
    if (m == glm::dmat4(1.0) && !std::holds_alternative<Mesh>(o.shape) && !std::holds_alternative<SphereSet>(o.shape) &&
        !std::holds_alternative<Sor>(o.shape) && !std::holds_alternative<Prism>(o.shape) &&
        !std::holds_alternative<Lathe>(o.shape) &&
        !std::holds_alternative<Superellipsoid>(o.shape)) {
        o.placement.reset();
        return;
    }
    Placement p{m, glm::inverse(m), false};
    p.shape_in_object_space = !std::visit(Absorber{m}, o.shape);
    o.placement = p;
}

void translate(Object& o, const dvec3& offset) {
    if (o.placement) {
        o.placement->to_world[3] += glm::dvec4(offset, 0.0);
        o.placement->to_object[3] -= glm::dvec4(glm::dmat3(o.placement->to_object) * offset, 0.0);
        if (o.placement->shape_in_object_space) return;
    }
    translate(o.shape, offset);
}

}  // namespace lancer

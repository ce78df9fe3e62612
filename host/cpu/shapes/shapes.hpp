#pragma once
// Ray/shape intersection for the CPU reference, one .cpp per shape family (the twins of
// shaders/shapes/*.glsl). intersect() returns the nearest hit with t in (t_min, t_max), or
// nothing, with the unit geometric normal there (not yet turned toward the ray) and the
// surface's own (u, v) where it has them.
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "cpu/ray.hpp"
#include "surface/bezier_patch.hpp"
#include "surface/implicit_surface.hpp"
#include "surface/parametric_surface.hpp"

namespace lancer::cpu {

struct SurfaceHit {
    double t;
    dvec3 normal;
    glm::dvec2 uv{0.0};
    int part = -1;  // which patch of a Bezier surface
};

std::optional<SurfaceHit> intersect(const Sphere& s, const Ray& ray, double t_min, double t_max);
// The nearest t in (t_min, t_max) where a ray with a unit direction meets the sphere (sphere.cpp).
std::optional<double> sphere_hit_t(const dvec3& center, double radius, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const Plane& p, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const Rectangle& r, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const Box& b, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const Disc& d, const Ray& ray, double t_min, double t_max);
// uv.x is which part was hit: 0 the side, 1 the base's disc, 2 the cap's (texture_uv reads it).
std::optional<SurfaceHit> intersect(const Cone& c, const Ray& ray, double t_min, double t_max);
// The nearest root of the torus's quartic in (t_min, t_max), isolated by Bernstein subdivision
// (certified: a piece is dropped only when its Bernstein coefficients prove no root, a root is
// reported where they prove exactly one, or where a piece of 1e-12 of the segment cannot be
// told from a touching point). Any ray direction length works.
std::optional<SurfaceHit> intersect(const Torus& o, const Ray& ray, double t_min, double t_max);
// The nearest point in (t_min, t_max) where the blob's field reaches its threshold: along the ray
// each component's field is a quartic in t between the points where the ray enters or leaves its
// support or crosses its segment's end planes, so the field's sum is one quartic per stretch
// between those points, whose roots are isolated there by Bernstein subdivision (certified, as
// the torus's). The normal is the field's gradient, turned outward. Any ray direction length.
std::optional<SurfaceHit> intersect(const Blob& o, const Ray& ray, double t_min, double t_max);
// The nearest hit on the surface of revolution (sor.cpp): on each segment whose slab and
// bounding cylinder the ray crosses, x^2 + z^2 - r^2(y) is a cubic along the ray, its roots
// isolated by Bernstein subdivision (certified, as the torus's); the base and cap discs unless
// open. Any ray direction length.
std::optional<SurfaceHit> intersect(const Sor& o, const Ray& ray, double t_min, double t_max);
// The nearest hit on the prism (prism.cpp): one walk of the outline's tree along the ray's line in
// the outline plane, from the slab's entry: every crossing beyond it (certified roots of each
// segment's Bezier of its side of the line), the nearest a wall, their parity the caps'. Any ray
// direction length.
std::optional<SurfaceHit> intersect(const Prism& o, const Ray& ray, double t_min, double t_max);
// The nearest hit on the lathe (lathe.cpp): on each segment whose band the ray crosses, the ray's
// distance from the axis squared less r(s)^2, with t eliminated through y(s), is a polynomial of
// degree 2 x the lathe's degree in the curve's parameter s, its roots isolated by Bernstein
// subdivision (certified, as the torus's), t then from y(s) or, for a ray more across the axis
// than along it, from the circle of radius r(s). uv = (segment, s). Any ray direction length.
std::optional<SurfaceHit> intersect(const Lathe& o, const Ray& ray, double t_min, double t_max);
// The nearest hit on the superellipsoid (superellipsoid.cpp), in its own coordinates: F, the
// q-norm of (the p-norm of (x, y), z), is convex along the ray, so Newton's method from the box's
// entry (its exit for the far root) closes on the root from outside without passing it; the root
// is then bracketed (F > 1 on one side, F < 1 on the other) and refined to double precision. A
// ray along which F's tangent turns upward while F > 1 misses. Any ray direction length.
std::optional<SurfaceHit> intersect(const Superellipsoid& o, const Ray& ray, double t_min, double t_max);
// Certified (interval Newton) search for the nearest root; `normal` is surface_normal() there
// and `uv` the surface's (u, v). Any ray direction length works: t is the ray's own parameter.
std::optional<SurfaceHit> intersect(const surface::ParametricSurface& s, const Ray& ray, double t_min, double t_max);
inline std::optional<SurfaceHit> intersect(const ParametricObject& p, const Ray& ray, double t_min, double t_max) {
    return intersect(*p.surface, ray, t_min, t_max);
}

// Implicit surfaces f(x, y, z) = 0 (implicit.cpp): every root along the ray inside the box with t
// in (t_min, t_max), nearest first. A Simple root is proved to lie within 1e-10 of the box's
// diagonal (along the ray) of a zero of f where f changes sign; a Touching one is where the ray
// touches the surface or crosses a singular point to within rounding (nothing could be proved,
// but f's enclosure there contains 0). intersect() reports the nearest, with the normal from
// the gradient (implicit_normal) and uv the hit's x and y across the box.
enum class RootKind { Simple, Touching };
struct ImplicitRoot {
    double t;
    RootKind kind;
};
std::vector<ImplicitRoot> implicit_roots(const surface::ImplicitSurface& s, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const ImplicitObject& o, const Ray& ray, double t_min, double t_max);

// The closed shapes that are not convex (SHAPE_CLOSED: CSG walks their inside along a line):
// every root along the whole line, nearest first, and whether a point is inside (f < 0; an
// implicit surface's reader proved f > 0 on its box's faces before it let it into CSG).
std::vector<double> roots_on_line(const Torus& o, const Ray& ray);
bool inside(const Torus& o, const dvec3& p);
std::vector<double> roots_on_line(const ImplicitObject& o, const Ray& ray);
bool inside(const ImplicitObject& o, const dvec3& p);
std::vector<double> roots_on_line(const Blob& o, const Ray& ray);
bool inside(const Blob& o, const dvec3& p);
std::vector<double> roots_on_line(const Sor& o, const Ray& ray);  // the curve's and the discs'
bool inside(const Sor& o, const dvec3& p);
std::vector<double> roots_on_line(const Prism& o, const Ray& ray);  // the walls' and the caps'
bool inside(const Prism& o, const dvec3& p);
std::vector<double> roots_on_line(const Lathe& o, const Ray& ray);
bool inside(const Lathe& o, const dvec3& p);  // even-odd, as POV-Ray's; never for an open lathe

// The surfaces that close a solid (SHAPE_ORIENTED: CSG walks their inside along a line):
// every point where the ray's line crosses the surface with t in (t0, t1), nearest first, and
// whether it leaves the solid there (its normal, turned by `outward`, along the ray). A root
// found twice, or a touching point, may repeat or have either side: CSG's walk ignores an entry
// while inside and an exit while outside.
struct LineCrossing {
    double t;
    bool leaving;
};
std::vector<LineCrossing> crossings_on_line(const ParametricObject& o, const Ray& ray, double t0, double t1);
std::vector<LineCrossing> crossings_on_line(const BezierSurface& s, const Ray& ray, double t0, double t1);
std::vector<LineCrossing> crossings_on_line(const Mesh& m, const Ray& ray, double t0, double t1);

// CSG (csg.cpp): the nearest point of the combination's surface, a leaf's hit (part: which leaf;
// the normal and (u, v) the leaf's there).
std::optional<SurfaceHit> intersect(const Csg& c, const Ray& ray, double t_min, double t_max);

// Triangle meshes (mesh.cpp), in the file's coordinates (an object's placement carries rays
// there): the nearest triangle hit by Woop, Benthin and Wald's watertight test (2013), through
// the mesh's own tree (MeshGeometry::tree); `part` the triangle, `uv` the hit's barycentric
// weights of its second and third vertices. Where two triangles share an edge, a ray through it
// hits at least one of them: no cracks. Any ray direction length works.
std::optional<SurfaceHit> intersect(const Mesh& m, const Ray& ray, double t_min, double t_max);
// Triangle `triangle`'s interpolated vertex normal at barycentric (b1, b2), in the world (through
// `placed`), on the side of `facing`; where the vertex normals cancel, `facing` itself.
dvec3 mesh_shading_normal(const Mesh& m, const Placement& placed, int triangle, const glm::dvec2& b, const dvec3& facing);
// The file's (u, v) interpolated; without any, the barycentric weights themselves.
glm::dvec2 mesh_texture_uv(const Mesh& m, int triangle, const glm::dvec2& b);

// Sphere sets (spheres.cpp), in the set's coordinates (its placement carries rays there): the
// nearest sphere through the set's own tree (SphereCloud::tree); `part` the sphere. The ray's
// direction must be unit.
std::optional<SurfaceHit> intersect(const SphereSet& s, const Ray& ray, double t_min, double t_max);
// Sphere `sphere`'s texture (u, v) at p (the set's coordinates): a sphere's, in the set's axes.
glm::dvec2 sphere_set_texture_uv(const SphereSet& s, int sphere, const dvec3& p);

// The ray in which an object's shape is tested (placed.cpp): the world's, or its object's where
// the shape keeps its own coordinates, with a unit direction; t there is k times the world's.
Ray shape_ray(const Object& o, const Ray& ray, double& k);
// An object's nearest hit: its shape's, carried through its placement where the shape keeps its
// own coordinates (placed.cpp); the normal is the world's.
std::optional<SurfaceHit> intersect(const Object& o, const Ray& ray, double t_min, double t_max);

// Texture coordinates (u, v) at a surface point p, for shapes whose intersection does not already
// give them (docs/scene-format.md, "Texture mapping"). Rectangles, Bezier and parametric
// surfaces use the (u, v) of their hits.
glm::dvec2 texture_uv(const Sphere& s, const dvec3& p);
glm::dvec2 texture_uv(const Plane& p, const dvec3& point);
glm::dvec2 texture_uv(const Box& b, const dvec3& p, const dvec3& face_normal);
glm::dvec2 texture_uv(const Disc& d, const dvec3& p);
glm::dvec2 texture_uv(const Cone& c, const dvec3& p, int part);
glm::dvec2 texture_uv(const Torus& o, const dvec3& p);
glm::dvec2 texture_uv(const Blob& o, const dvec3& p);  // x and y across its box
glm::dvec2 texture_uv(const Superellipsoid& o, const dvec3& p);  // x and y across [-1.01, 1.01]^2
glm::dvec2 texture_uv(const Sor& o, const dvec3& p);   // the angle about y, the height from bottom to top
glm::dvec2 texture_uv(const Prism& o, const dvec3& p); // (x, z): planar
glm::dvec2 texture_uv(const Lathe& o, const dvec3& p, const glm::dvec2& hit_uv);  // the angle, POV-Ray's v

// Bicubic (rational) Bezier patches, exactly, by resultant + generalized eigenvalues (bezier.cpp).
// The ray's direction need not be unit length: t is in units of it. intersect_all returns every
// distinct hit in (t_min, t_max), nearest first; intersect the nearest, with uv = (u, v) and the
// patch's robust unit normal there (surface::unit_normal).
struct PatchHit {
    double t, u, v;
};
std::vector<PatchHit> intersect_all(const surface::BezierPatch& p, const Ray& ray, double t_min, double t_max);
std::optional<SurfaceHit> intersect(const surface::BezierPatch& p, const Ray& ray, double t_min, double t_max);
// The nearest hit over a whole patch set, with `part` the index of the patch hit.
std::optional<SurfaceHit> intersect(const BezierSurface& s, const Ray& ray, double t_min, double t_max);

}  // namespace lancer::cpu

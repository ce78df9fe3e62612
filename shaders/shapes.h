// The shape registry, compiled as C++ (the scene model, both renderers) and as GLSL: one row per
// shape type, X(NAME, name, Type, type, traits), in the order of the type numbers
// (Primitive::type; the alternatives of the scene model's Shape, whose C++ type is Type). Each
// shape has shaders/shapes/<name>.glsl and host/cpu/shapes/<name>.cpp, and every rule about
// shapes reads its traits here (docs/adding-a-shape.md):
//   SHAPE_BOUNDED    a finite box: in the BVH; else tested by every ray, as planes are;
//   SHAPE_CHEAP      a closed-form test of a few dozen operations. Where every shape of a scene
//                    is cheap, camera and shadow rays may take direction grids and shadow rays a
//                    lean path; a few cheap bounded shapes beside costly ones stay outside the
//                    BVH, in loops of their own, with a box around each family;
//   SHAPE_SHEET      no inside: refraction passes it as a thin pane instead of entering a medium;
//   SHAPE_GENERATED  its GLSL comes from the scene's expressions (surface_functions.glsl);
//   SHAPE_SOLID      convex and closed (a plane: the half-space behind its normal), so that its
//                    inside along any line is one interval, from its first hit from -infinity to
//                    the reversed ray's: it may be an operand of CSG
//                    (shaders/shapes/csg.glsl; a cone only when capped, as its reader checks);
//   SHAPE_CLOSED     closed but not convex, with f < 0 inside: its inside along a line is walked
//                    root by root, each stretch between roots told by f's sign at its middle
//                    (name_inside): it may be an operand of CSG too (an implicit surface only
//                    where its reader proved f > 0 on its box's faces);
//   SHAPE_ORIENTED   a surface that may close a solid, with the side its normals face: a Bezier
//                    or parametric surface that its reader proved closed where the user declared
//                    it so (`closed = true`), a mesh whose edges all pair up: it may be an operand
//                    of CSG, walked root by root, each root entering or leaving by its normal's side;
//   SHAPE_IN_PIECES  packed as many primitives (Bezier sub-patches, parametric cells), which a CSG
//                    leaf of it walks in runs (shaders/shapes/csg.glsl);
//   SHAPE_KEEPS_LOCALS  lavapipe's code for it is faster where the host leaves the SPIR-V's
//                    local variables alone (gpu/shaders/spirv_specialize.hpp: the Bezier clipper 7-9%,
//                    the parametric search 2-5%).
#ifndef LANCER_SHAPES_H
#define LANCER_SHAPES_H

#define LANCER_SHAPES(X)                                                              \
    X(SPHERE, sphere, Sphere, 0, SHAPE_BOUNDED | SHAPE_CHEAP | SHAPE_SOLID)           \
    X(PLANE, plane, Plane, 1, SHAPE_CHEAP | SHAPE_SOLID)                              \
    X(RECTANGLE, rectangle, Rectangle, 2, SHAPE_BOUNDED | SHAPE_CHEAP | SHAPE_SHEET)  \
    X(BOX, box, Box, 3, SHAPE_BOUNDED | SHAPE_CHEAP | SHAPE_SOLID)                    \
    X(BEZIER, bezier, BezierSurface, 4, SHAPE_BOUNDED | SHAPE_KEEPS_LOCALS | SHAPE_ORIENTED | SHAPE_IN_PIECES)\
    X(PARAMETRIC, parametric, ParametricObject, 5, SHAPE_BOUNDED | SHAPE_GENERATED | SHAPE_KEEPS_LOCALS | SHAPE_ORIENTED | SHAPE_IN_PIECES)\
    X(IMPLICIT, implicit, ImplicitObject, 6, SHAPE_BOUNDED | SHAPE_GENERATED | SHAPE_CLOSED)             \
    X(DISC, disc, Disc, 7, SHAPE_BOUNDED | SHAPE_CHEAP | SHAPE_SHEET)                                    \
    X(CONE, cone, Cone, 8, SHAPE_BOUNDED | SHAPE_CHEAP | SHAPE_SOLID)                                    \
    X(TORUS, torus, Torus, 9, SHAPE_BOUNDED | SHAPE_CLOSED)                                              \
    X(CSG, csg, Csg, 10, SHAPE_BOUNDED)                                                                  \
    X(MESH, mesh, Mesh, 11, SHAPE_BOUNDED | SHAPE_ORIENTED)                                                             \
    X(SPHERES, spheres, SphereSet, 12, SHAPE_BOUNDED)                                                   \
    X(BLOB, blob, Blob, 13, SHAPE_BOUNDED | SHAPE_CLOSED)                                                \
    X(SOR, sor, Sor, 14, SHAPE_BOUNDED | SHAPE_CLOSED)                                                  \
    X(PRISM, prism, Prism, 15, SHAPE_BOUNDED | SHAPE_CLOSED)                                                \
    X(LATHE, lathe, Lathe, 16, SHAPE_BOUNDED | SHAPE_CLOSED)                                                \
    X(SUPERELLIPSOID, superellipsoid, Superellipsoid, 17, SHAPE_BOUNDED | SHAPE_SOLID)

#ifdef __cplusplus
#include <cstdint>
namespace lancer {
#define LANCER_SHAPE_CONST inline constexpr std::uint32_t
#else
#define LANCER_SHAPE_CONST const uint
#endif

LANCER_SHAPE_CONST SHAPE_BOUNDED = 1u;
LANCER_SHAPE_CONST SHAPE_CHEAP = 2u;
LANCER_SHAPE_CONST SHAPE_SHEET = 4u;
LANCER_SHAPE_CONST SHAPE_GENERATED = 8u;
LANCER_SHAPE_CONST SHAPE_KEEPS_LOCALS = 16u;
LANCER_SHAPE_CONST SHAPE_SOLID = 32u;
LANCER_SHAPE_CONST SHAPE_CLOSED = 64u;
LANCER_SHAPE_CONST SHAPE_ORIENTED = 128u;
LANCER_SHAPE_CONST SHAPE_IN_PIECES = 256u;

// A CSG program (Csg::program, shaders/shapes/csg.glsl): postfix over whether a point is inside
// each of the node's leaves. An op is CSG_LEAF | k << 4 (push leaf k's inside) or one of the
// others (pop b, pop a, push a AND b, a OR b, a AND NOT b; or flip the top).
LANCER_SHAPE_CONST CSG_LEAF = 0u;
LANCER_SHAPE_CONST CSG_AND = 1u;
LANCER_SHAPE_CONST CSG_OR = 2u;
LANCER_SHAPE_CONST CSG_AND_NOT = 3u;
LANCER_SHAPE_CONST CSG_NOT = 4u;
LANCER_SHAPE_CONST CSG_MAX_LEAVES = 32u;  // the insides are the bits of a uint

// A blob (shaders/shapes/blob.glsl) is searched along a ray in windows of at most this many of
// its components, nearest first: its reader refuses a blob where more may overlap at a point.
LANCER_SHAPE_CONST BLOB_MAX_OVERLAP = 16u;

#define LANCER_SHAPE_TYPE(NAME, name, Type, type, traits) LANCER_SHAPE_CONST SHAPE_##NAME = type;
LANCER_SHAPES(LANCER_SHAPE_TYPE)
#undef LANCER_SHAPE_TYPE
#define LANCER_SHAPE_COUNTER(NAME, name, Type, type, traits) +1u
LANCER_SHAPE_CONST SHAPE_COUNT = 0u LANCER_SHAPES(LANCER_SHAPE_COUNTER);
#undef LANCER_SHAPE_COUNTER

// The shape sets of the tracer modules built beside the whole one (host/CMakeLists.txt): a
// scene of one set's types alone starts from a module of 40-52% of the words, which lancer's
// specialisation at start-up goes through in half to two thirds of the time (docs/performance.md).
#define LANCER_CHEAP_TYPE_BIT(NAME, name, Type, type, traits) | ((((traits) & SHAPE_CHEAP) != 0u) ? 1u << (type) : 0u)
LANCER_SHAPE_CONST CHEAP_SHAPE_TYPES = 0u LANCER_SHAPES(LANCER_CHEAP_TYPE_BIT);
#undef LANCER_CHEAP_TYPE_BIT
// ... and the everyday shapes of small code beside them; not CSG, the lathes' and prisms'
// splines, blobs or Bezier patches (the generated surfaces are compiled per scene anyway).
LANCER_SHAPE_CONST COMMON_SHAPE_TYPES = CHEAP_SHAPE_TYPES | (1u << SHAPE_TORUS) | (1u << SHAPE_MESH) |
                                        (1u << SHAPE_SPHERES) | (1u << SHAPE_SUPERELLIPSOID);

// The traits of shape type t, a constant wherever t is.
#define LANCER_SHAPE_TRAITS_CASE(NAME, name, Type, type, traits) (t) == SHAPE_##NAME ? (traits) :
#ifdef __cplusplus
constexpr std::uint32_t shape_traits(std::uint32_t t) { return LANCER_SHAPES(LANCER_SHAPE_TRAITS_CASE) 0u; }
constexpr bool shape_has(std::uint32_t t, std::uint32_t trait) { return (shape_traits(t) & trait) != 0u; }
// Cheap and bounded: kept outside a BVH of costly shapes, in a family loop with its box.
constexpr bool shape_is_boxable(std::uint32_t t) { return shape_has(t, SHAPE_BOUNDED) && shape_has(t, SHAPE_CHEAP); }

#define LANCER_SHAPE_NAME_CASE(NAME, name, Type, type, traits) (t) == SHAPE_##NAME ? #name :
constexpr const char* shape_name(std::uint32_t t) { return LANCER_SHAPES(LANCER_SHAPE_NAME_CASE) "unknown"; }
#undef LANCER_SHAPE_NAME_CASE

constexpr bool shape_types_are_dense() {
    std::uint32_t next = 0;
#define LANCER_SHAPE_ORDER(NAME, name, Type, type, traits) \
    if (type != next++) return false;
    LANCER_SHAPES(LANCER_SHAPE_ORDER)
#undef LANCER_SHAPE_ORDER
    return true;
}
static_assert(shape_types_are_dense(), "LANCER_SHAPES: types must be 0, 1, 2, ... in row order");
}  // namespace lancer
#else
uint shape_traits(uint t) { return LANCER_SHAPES(LANCER_SHAPE_TRAITS_CASE) 0u; }
#endif
#undef LANCER_SHAPE_TRAITS_CASE

#undef LANCER_SHAPE_CONST
#endif  // LANCER_SHAPES_H

// The one definition of the interface between the host and the shader: every GPU struct, every
// descriptor of the tracer's set and every specialisation constant.
//
// This header is compiled twice: by the C++ host (through host/gpu/layout.hpp) and by glslang
// as part of the compute shader (GL_GOOGLE_include_directive). Three tables below drive both:
//   - each struct is a list of 16-byte rows (LANCER_ROWS_*), from which come the C++ struct,
//     the GLSL struct and the GLSL function that reads one from a texel buffer
//     (shaders/interface.glsl), so a member added here is at once on both sides;
//   - LANCER_RESOURCES lists the descriptors: the host's set layout, pool, writes, buffers and
//     memory budget (host/gpu/trace_resources.*, host/gpu/vulkan/) and the shader's declarations
//     (interface.glsl);
//   - LANCER_FEATURES lists the specialisation constants: the host's ShaderFeatures and
//     the shader's constants.
// Shape types come from the shape registry (shapes.h).
// Rows are vec4s, uvec4s or four 32-bit scalars, so std140, std430, a texel buffer's RGBA32 texels and
// the C++ ABI all agree without padding tricks; tests/unit/layout_reflection_test.cpp checks it
// against glslang's reflection and tests/render/interface_test.cpp reads every struct back
// through the shader's readers.
#ifndef LANCER_LAYOUT_H
#define LANCER_LAYOUT_H

#include "shapes.h"

#ifdef __cplusplus
#include <cstdint>
#include <glm/vec4.hpp>
namespace lancer::gpu {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using lancer::SHAPE_COUNT;
#define LANCER_SHAPE_NAME(NAME, name, Type, type, traits) using lancer::SHAPE_##NAME;
LANCER_SHAPES(LANCER_SHAPE_NAME)
#undef LANCER_SHAPE_NAME
using uint = std::uint32_t;
#define LANCER_CONST constexpr uint
#else
#define LANCER_CONST const uint
#endif

// Workgroup shape: 8x8 = 64 invocations (lavapipe: 64-256 all within noise, 4x4 halves speed).
LANCER_CONST WORKGROUP_X = 8;
LANCER_CONST WORKGROUP_Y = 8;
#ifdef __cplusplus
static_assert(WORKGROUP_X == 8 && WORKGROUP_Y == 8, "trace.comp's z_order_position orders an 8 x 8 workgroup");
#endif

// Primitive::type is a shape type of the registry (shapes.h); p0..p2 and data hold what the
// shape's file says.
// Per-shape uints of FrameParams are packed four to a uvec4.
LANCER_CONST SHAPE_QUADS = (SHAPE_COUNT + 3u) / 4u;

// A primitive index that names none.
LANCER_CONST NO_PRIMITIVE = 0xffffffffu;

// Material::pattern values.
LANCER_CONST PATTERN_SOLID = 0;
LANCER_CONST PATTERN_CHECKER = 1;

// Material::texture_map, color_pattern and bump_pattern when the material has none.
LANCER_CONST NO_MAP = 0xffffffffu;

// TextureInfo::flags bits.
LANCER_CONST TEXTURE_CLAMP_U = 1;  // else repeat
LANCER_CONST TEXTURE_CLAMP_V = 2;
LANCER_CONST TEXTURE_NEAREST = 4;  // else bilinear

// PatternInfo::type values.
LANCER_CONST PATTERN_NOISE = 0;
LANCER_CONST PATTERN_TURBULENCE = 1;
LANCER_CONST PATTERN_MARBLE = 2;
LANCER_CONST PATTERN_WOOD = 3;
LANCER_CONST PATTERN_MAX_COLORS = 8;  // stops of a colour ramp (scene/limits.hpp: kMaxPatternColors)

// Material::highlight values.
LANCER_CONST HIGHLIGHT_PHONG = 0;
LANCER_CONST HIGHLIGHT_BLINN = 1;

// The direction grids (DirectionGrid): the eye's, its mirror image's in a flat mirror
// (FrameParams::mirror_plane), then one for each of the first lights.
LANCER_CONST DIRECTION_GRID_EYE = 0;
LANCER_CONST DIRECTION_GRID_MIRROR = 1;
LANCER_CONST DIRECTION_GRID_LIGHT = 2;
LANCER_CONST DIRECTION_GRID_COUNT = 8;
LANCER_CONST NO_GRID = 0xffffffffu;

// Light::type values.
LANCER_CONST LIGHT_POINT = 0;
LANCER_CONST LIGHT_SPOT = 1;
LANCER_CONST LIGHT_AREA = 2;

// Material::model values (docs/scene-format.md, "Microfacet materials").
LANCER_CONST MODEL_PHONG = 0;
LANCER_CONST MODEL_MICROFACET_METAL = 1;
LANCER_CONST MODEL_MICROFACET_GLASS = 2;
LANCER_CONST ENERGY_TABLE_SIZE = 32;  // E(mu) at mu = i / 31 (host/optics/energy.hpp: EnergyTable::kSize)

// Photon mapping (docs/scene-format.md, "[photons]"): workgroup size of the photon pass and of
// the grid build (shaders/photons.comp, photon_grid.comp), and the grid build's steps.
LANCER_CONST PHOTON_WORKGROUP = 64;
LANCER_CONST GRID_CLEAR = 0;
LANCER_CONST GRID_COUNT = 1;
LANCER_CONST GRID_SCAN = 2;
LANCER_CONST GRID_BLOCKS = 3;
LANCER_CONST GRID_OFFSET = 4;
LANCER_CONST GRID_SCATTER = 5;

// Adaptive anti-aliasing's choice of the pixels to refine on the GPU (shaders/refine_select.comp):
// its workgroup size, the pixels each invocation takes, a block of its prefix sums (a workgroup's
// pixels), its steps (SelectStep::kind) and the bits of refine_flags.
LANCER_CONST SELECT_WORKGROUP = 64;
LANCER_CONST SELECT_RUN = 16;
LANCER_CONST SELECT_BLOCK = SELECT_WORKGROUP * SELECT_RUN;
LANCER_CONST SELECT_ENCODE = 0;
LANCER_CONST SELECT_MERGE = 1;
LANCER_CONST SELECT_FLAG = 2;
LANCER_CONST SELECT_BLOCKS = 3;
LANCER_CONST SELECT_SCATTER = 4;
LANCER_CONST REFINE_CANDIDATE = 1;  // the last step traced it (before the first: every pixel)
LANCER_CONST REFINE_SPREAD = 2;     // its samples in the last step spread by more than the threshold

// ---------------------------------------------------------------------------------------------
// Structs, as lists of rows. LANCER_ROWS_Name(VEC4, VEC4S, SCALARS, UVEC4S) lists the rows of struct
// Name in order: VEC4(name) a vec4; VEC4S(name, n) an array of n vec4s; SCALARS(T0, n0, T1, n1,
// T2, n2, T3, n3) four 32-bit scalars (uint, int or float); UVEC4S(name, n) an array of n uvec4s. Comments go in /* */ (a // comment
// would swallow the macro's next line).
// ---------------------------------------------------------------------------------------------

#define LANCER_ROWS_Primitive(VEC4, VEC4S, SCALARS, UVEC4S)                                             \
    SCALARS(uint, type, uint, material,                                                         \
            uint, data,   /* shape-specific index into a further array (patch shapes), else 0 */ \
            uint, object) /* index of the scene object it came from */                          \
    VEC4(p0) VEC4(p1) VEC4(p2)

// A bicubic (rational) Bezier sub-patch, ready for Bezier clipping. Control points are stored
// relative to `origin` (the leaf's centre) so that float keeps its precision far from the
// world origin.
#define LANCER_ROWS_PatchLeaf(VEC4, VEC4S, SCALARS, UVEC4S)                                                      \
    VEC4S(points, 16) /* xyz = control point - origin, w = weight (1 if polynomial); row-major, i along u */ \
    VEC4(origin)      /* xyz; w = index of the patch within its surface (for tests and texture lookups) */   \
    VEC4(domain)      /* (u0, u1, v0, v1): where this leaf lies in its patch's parameter square */

// Per parametric surface: the affine map from the user's (x, y, z) to world space, so moving an
// object only rewrites this array, never the generated shader code:
// world = (dot(row0.xyz, p) + row0.w, dot(row1.xyz, p) + row1.w, dot(row2.xyz, p) + row2.w),
// and its inverse (inverse0..2, the same form), which carries rays into the surface's
// coordinates, where the intersector works.
#define LANCER_ROWS_SurfaceInfo(VEC4, VEC4S, SCALARS, UVEC4S) \
    VEC4(row0) VEC4(row1) VEC4(row2)                  \
    VEC4(inverse0) VEC4(inverse1) VEC4(inverse2)      \
    VEC4(domain) /* (u0, u1, v0, v1) of the whole surface */

// Per implicit surface: the affine map from world space to the coordinates its f(x, y, z) is
// written in (the inverse of its transform), so moving an object only rewrites this array,
// never the generated shader code: p = (dot(row0.xyz, w) + row0.w, dot(row1.xyz, w) + row1.w,
// dot(row2.xyz, w) + row2.w) for a world point w; directions without the w terms, and normals by
// the transpose.
#define LANCER_ROWS_ImplicitInfo(VEC4, VEC4S, SCALARS, UVEC4S)                                          \
    VEC4(row0) VEC4(row1) VEC4(row2)                                                                \
    VEC4(texture_box) /* (x0, y0, x1, y1) of the surface's box, which maps textures; the primitive's */ \
                      /* box is where the surface can be in it (surface::shrink_to_surface), searched */

// Per scene object, where some object has a transform (PLACED_OBJECTS): the affine map from the
// GPU's coordinates to the object's own (row0..2 in ImplicitInfo's form), where its checker and
// patterns are evaluated and, for a shape kept in its own coordinates (an ellipsoid, a turned
// box: OBJECT_SPACE_SHAPES), its rays are traced (shaders/placement.glsl).
#define LANCER_ROWS_ObjectFrame(VEC4, VEC4S, SCALARS, UVEC4S)                                          \
    VEC4(row0) VEC4(row1) VEC4(row2)                                                                \
    VEC4(world0) VEC4(world1) VEC4(world2) /* and its inverse, object -> world, in the same form */   \
    SCALARS(float, stretch,    /* the most object -> world multiplies a length by (its inf-norm) */  \
            float, mean_scale, /* the cube root of its determinant: a bump's depth scales with it */ \
            uint, in_object_space, /* 1: the object's primitives are in its own coordinates */       \
            uint, world) /* 1: no transform: the world's coordinates (the GPU's plus the anchor); its */ \
                         /* checker is then the GPU point's, with the material's phase (precise far off) */

// A CSG object (shaders/shapes/csg.glsl): its leaves are the primitives [first_leaf, first_leaf +
// leaf_count), stored after every primitive the tracer traverses; its program the CSG_* ops
// csg_ops[first_op, first_op + op_count) (shapes.h).
// A triangle mesh or a sphere set on the GPU (shapes/mesh.glsl, shapes/spheres.glsl), once
// however many objects place it (each placement is a primitive whose data is its index): its tree
// (MESH_NODES, children and element ranges as absolute indices; shapes/element_tree.glsl) over
// its elements (MESH_TRIANGLES or SET_SPHERES, in leaf order), in the file's coordinates; where
// placements take the file's own materials, each element's (MESH_MATERIALS from first_material,
// in the same order; else NO_MAP).
#define LANCER_ROWS_MeshInfo(VEC4, VEC4S, SCALARS, UVEC4S) \
    SCALARS(uint, first_node, uint, first_element, uint, element_count, uint, first_material)
// A node of a mesh's tree: as the scene's BvhNode (a type of its own: each array has one).
#define LANCER_ROWS_MeshNode(VEC4, VEC4S, SCALARS, UVEC4S) \
    VEC4(lo) /* xyz */                              \
    VEC4(hi) /* xyz */                              \
    SCALARS(uint, first, uint, count, uint, reserved0, uint, reserved1)
// A triangle: its vertices (w: texture u) and vertex normals (unit; w: texture v). A mesh
// without texture coordinates has each vertex's barycentric corner, (0, 0), (1, 0), (0, 1).
#define LANCER_ROWS_MeshTriangle(VEC4, VEC4S, SCALARS, UVEC4S) \
    VEC4(v0) VEC4(v1) VEC4(v2) VEC4(n0) VEC4(n1) VEC4(n2)

// A sphere of a sphere set: (centre, radius), the file's floats.
#define LANCER_ROWS_SetSphere(VEC4, VEC4S, SCALARS, UVEC4S) VEC4(sphere)

// A component of a blob (shapes/blob.glsl): its segment from a to b (a == b: a sphere component),
// in the order of its blob's tree's leaves (MESH_NODES, through the blob's MeshInfo).
#define LANCER_ROWS_BlobElement(VEC4, VEC4S, SCALARS, UVEC4S) \
    VEC4(a) /* xyz; w: radius */                                \
    VEC4(b) /* xyz; w: strength */

// A segment of a surface of revolution (shapes/sor.glsl): its radius squared about its bottom,
// ((a u + b) u + c) u + d with u = y - y0, on [y0, y1], and its largest radius.
#define LANCER_ROWS_SorBand(VEC4, VEC4S, SCALARS, UVEC4S) \
    VEC4(coefficients) /* a, b, c, d */                 \
    VEC4(span)         /* y0, y1, largest radius, 0 */

// A segment of a prism's outline (shapes/prism.glsl): a 2-D Bezier of degree 1 to 3, its control
// points' x and z (those beyond its degree repeat its last), and its degree.
#define LANCER_ROWS_PrismCurve(VEC4, VEC4S, SCALARS, UVEC4S) \
    VEC4(xs)   /* x of control points 0..3 */              \
    VEC4(zs)   /* z of control points 0..3 */              \
    VEC4(info) /* degree, 0, 0, 0 */
// A segment of a lathe (shapes/lathe.glsl): its radius and height as cubics in its parameter s
// in [0, 1], power coefficients about s = 1/2 (x + y h + z h^2 + w h^3 with h = s - 1/2), and its
// band: the largest radius, the lowest and highest heights, and the side its outward normal
// takes (+1: (y'(s), -r'(s)), -1: the opposite).
#define LANCER_ROWS_LatheBand(VEC4, VEC4S, SCALARS, UVEC4S) \
    VEC4(radius)  /* r(s) about s = 1/2 */                \
    VEC4(height)  /* y(s) about s = 1/2 */                \
    VEC4(band)    /* largest radius, lowest y, highest y, side */

#define LANCER_ROWS_CsgNode(VEC4, VEC4S, SCALARS, UVEC4S) \
    SCALARS(uint, first_leaf, uint, leaf_count, uint, first_op, uint, op_count)

// One cell of a parametric surface's domain, where the GPU searches for roots
// (shapes/parametric.glsl). S at the cell's centre and the bounds of S's partials over the whole
// (slightly widened) cell, in the surface's own coordinates, let the search decide most cells
// without evaluating S: no root, or at most one, which Newton's method then finds. The bounds of
// the second partials give tight bounds of the first over any part of the cell, from S's
// partials at that part's centre.
#define LANCER_ROWS_ParametricCell(VEC4, VEC4S, SCALARS, UVEC4S)                                        \
    VEC4(domain)  /* (u0, u1, v0, v1) */                                                        \
    VEC4(su_lo)   /* xyz = lower bounds of dS/du (-3.4e38: none); w = the surface index */      \
    VEC4(su_hi)   /* xyz = upper bounds of dS/du; w = how far float evaluation of S may stray */ \
    VEC4(sv_lo)   /* xyz = lower bounds of dS/dv */                                             \
    VEC4(sv_hi)   /* xyz = upper bounds of dS/dv */                                             \
    VEC4(centre)  /* xyz = S at the cell's centre; w = 1, or 0 where S is undefined there */     \
    VEC4(suu)     /* xyz = bounds of |d2S/du2| (3.4e38: none) */                                \
    VEC4(suv)     /* xyz = bounds of |d2S/dudv| */                                              \
    VEC4(svv)     /* xyz = bounds of |d2S/dv2| */

// A node of the bounding volume hierarchy over all bounded primitives (host/accel/bvh.hpp).
// Inner nodes (count == 0) have their children at first and first + 1; leaves cover the
// primitives [first, first + count). Boxes are rounded outward from double.
#define LANCER_ROWS_BvhNode(VEC4, VEC4S, SCALARS, UVEC4S) \
    VEC4(lo) /* xyz */                            \
    VEC4(hi) /* xyz */                            \
    SCALARS(uint, first, uint, count, uint, reserved0, uint, reserved1)

// A microfacet material (model != MODEL_PHONG) keeps its constants in the rows Phong's would
// use (shaders/microfacet_material.glsl): color.rgb = its tint, color2 = (eta, alpha = roughness^2),
// phong = (k, E_avg); a metal's energy table and multiple-scattering colour below.
#define LANCER_ROWS_Material(VEC4, VEC4S, SCALARS, UVEC4S)                                                  \
    VEC4(color)  /* rgb = pigment (checker: first colour), linear */                                \
    VEC4(color2) /* rgb = second checker colour */                                                  \
    VEC4(phong)  /* x = ambient, y = diffuse, z = specular, w = shininess (n_s) */                   \
    SCALARS(float, reflection, uint, pattern, float, checker_size,                                   \
            uint, model) /* MODEL_PHONG, MODEL_MICROFACET_METAL or MODEL_MICROFACET_GLASS */          \
    /* textures and patterns (shaders/appearance.glsl): indices, or NO_MAP */                        \
    SCALARS(uint, texture_map,   /* into textures: the pigment is multiplied by the image's colour */ \
            uint, color_pattern, /* into patterns: the pigment is multiplied by the pattern's colour */ \
            uint, bump_pattern,  /* into patterns: the shading normal is tilted by its gradient */   \
            uint, energy_table)  /* microfacet metals: their table in energy_tables */              \
    /* optics: refraction and the highlight model */                                                \
    VEC4(transmission) /* rgb = T, the fraction passed per channel (all 0: opaque); w = ior */      \
    VEC4(absorption)   /* rgb = Beer-Lambert coefficient per unit distance inside; w unused */      \
    VEC4(checker_phase) /* xyz = where the GPU's origin is in the solid checker (gpu/packing/float_anchor.hpp) */ \
    SCALARS(uint, checker_frame, /* into patterns (its rows only): a checker's own transform, or NO_MAP */ \
            uint, reserved0, uint, reserved1, uint, reserved2)                                      \
    SCALARS(uint, highlight, /* HIGHLIGHT_PHONG or HIGHLIGHT_BLINN */                               \
            float, ms_tint_r, float, ms_tint_g, float, ms_tint_b) /* microfacet metals: the multiple-scattering colour */

// An image as a material places it (shaders/texture.glsl). Image coordinates (s, t) run from
// (0, 0) at the image's bottom-left corner to (1, 1) at its top-right one.
#define LANCER_ROWS_TextureInfo(VEC4, VEC4S, SCALARS, UVEC4S)                                 \
    VEC4(to_image_s) /* s = dot(xy, uv) + z, uv the surface's texture coordinates */  \
    VEC4(to_image_t) /* t = dot(xy, uv) + z */                                        \
    SCALARS(uint, texel_offset, /* its first texel in texels; rows from the top */    \
            uint, width, uint, height,                                                \
            uint, flags) /* TEXTURE_CLAMP_U | TEXTURE_CLAMP_V | TEXTURE_NEAREST */

// A procedural pattern (shaders/pattern.glsl): a scalar function of the world position, shown
// through a colour ramp or used as a bump.
#define LANCER_ROWS_PatternInfo(VEC4, VEC4S, SCALARS, UVEC4S)                                                         \
    VEC4(row0) /* world -> pattern space: q = (dot(row0.xyz, p) + row0.w, dot(row1..), dot(row2..)) */         \
    VEC4(row1) VEC4(row2)                                                                                     \
    VEC4(params) /* x = turbulence, y = omega, z = lambda, w = bump strength (amount x mean scale) */          \
    SCALARS(uint, type, /* PATTERN_NOISE, ... */ uint, octaves, uint, color_count, uint, reserved)             \
    VEC4S(colors, PATTERN_MAX_COLORS) /* rgb = colour, w = its position on the ramp, ascending */

#define LANCER_ROWS_Light(VEC4, VEC4S, SCALARS, UVEC4S)                                                      \
    VEC4(position)  /* xyz = where it is (area light: the rectangle's centre); w = fall-off distance, 0 = none */ \
    VEC4(color)     /* rgb */                                                                        \
    VEC4(direction) /* spot: xyz = unit axis of the cone; w = POV-Ray's fade_power, 0 = 1/d^2 */      \
    VEC4(spot)      /* spot: x = cos(outer_angle), y = cos(inner_angle), z = tightness */            \
    VEC4(edge_u)    /* area: xyz = first edge (whole length) */                                      \
    VEC4(edge_v)    /* area: xyz = second edge */                                                    \
    SCALARS(uint, type,    /* LIGHT_POINT, LIGHT_SPOT or LIGHT_AREA */                               \
            uint, samples, /* area: n, for n x n shadow samples */                                   \
            uint, jitter,  /* area: 1 = each sample at a hashed place in its cell, 0 = at its centre */ \
            uint, reserved)

// A grid over the directions from one point, the eye, its mirror image in a flat mirror, or a
// point or spot light (gpu/packing/direction_grids.hpp): a ray along a half-line from `origin` (a camera
// ray, its reflection in the mirror, or a shadow ray's segment, which ends at its light) can hit
// only the primitives its direction's cell lists.
// A direction w has the cell of (dot(w, across_u), dot(w, across_v)) / dot(w, axis); none where
// dot(w, axis) <= 0 or outside the window: no primitive of the BVH lies that way.
#define LANCER_ROWS_DirectionGrid(VEC4, VEC4S, SCALARS, UVEC4S)                                             \
    VEC4(origin)   /* xyz */                                                                        \
    VEC4(axis)     /* xyz: unit */                                                                  \
    VEC4(across_u) /* xyz: unit, across the axis */                                                 \
    VEC4(across_v) /* xyz: unit, across both */                                                     \
    VEC4(window)   /* (u0, v0, columns per unit of u, rows per unit of v) */                        \
    SCALARS(uint, columns, uint, rows,                                                              \
            uint, first_cell, /* in grid_cells: the starts of its columns * rows lists, then their end */ \
            uint, valid)      /* 0: its rays go through the BVH */

// Per-render constants (a uniform block). The camera is given as the vectors from which the
// shader forms ray directions: dir = forward + ndc_x * right + ndc_y * up, with ndc in [-1, 1].
#define LANCER_ROWS_FrameParams(VEC4, VEC4S, SCALARS, UVEC4S)                                             \
    VEC4(eye) VEC4(forward)                                                                       \
    VEC4(right)      /* already scaled by tan(fov/2) * aspect */                                  \
    VEC4(up)         /* already scaled by tan(fov/2) */                                           \
    VEC4(background) /* rgb */                                                                    \
    VEC4(ambient)    /* rgb, the scene's ambient light */                                         \
    VEC4(fog)        /* rgb = its colour, w = 1 / its distance (SCENE_HAS_FOG) */                 \
    VEC4(fog_ground) /* ground fog: height Y(p) = dot(p, xyz) - w in altitudes; xyz = 0: constant */ \
    VEC4S(sky, PATTERN_MAX_COLORS) /* SCENE_HAS_SKY: its ramp, rgb and w = the stop */             \
    SCALARS(uint, width, uint, height,                                                            \
            uint, samples,   /* N: an N x N grid of rays per pixel */                             \
            uint, max_depth) /* reflection bounces after the camera ray */                        \
    SCALARS(uint, primitive_count, /* all primitives: the BVH's, then the unbounded ones (planes) */ \
            uint, light_count,                                                                    \
            uint, node_count,      /* 0 when nothing is bounded */                                \
            uint, unbounded_count) /* the last unbounded_count primitives (outside the BVH) are tested by every ray */ \
    SCALARS(uint, loop_probe, /* always 2: the trip count of trace.comp's loop_limit_reached() probe */ \
            uint, mirror_plane, /* a flat mirror whose reflections of camera rays take DIRECTION_GRID_MIRROR, or NO_PRIMITIVE */ \
            uint, sky_colors, /* the sky's ramp: its first sky_colors of sky */                \
            uint, sky_pattern) /* SKY_HAS_PATTERN: the sky's pattern in patterns (its ramp there) */ \
    /* the primitives outside the BVH, sorted by shape type: family t is [family_end[t - 1], */     \
    /* family_end[t]) (t = 0 from primitive_count - unbounded_count), read as [t / 4][t % 4] */   \
    UVEC4S(family_end, SHAPE_QUADS)                                                               \
    /* family boxes (gpu/packing/family_boxes.hpp): [2 t] around family t's members before */             \
    /* family_split[t], [2 t + 1] around the rest */                                             \
    VEC4S(family_lo, 2 * SHAPE_COUNT) VEC4S(family_hi, 2 * SHAPE_COUNT)                          \
    UVEC4S(family_split, SHAPE_QUADS)

// A light as photon mapping sees it (one per Light, in the same order).
#define LANCER_ROWS_Emitter(VEC4, VEC4S, SCALARS, UVEC4S)                                                   \
    VEC4(power) /* rgb = the power (W) of each photon it sends; w = P(this light or one before it) */ \
    VEC4(cone)  /* spot lights: x = the outer cone's solid angle over the spot's weighted one */

// A photon where it landed on a diffuse surface (shaders/photons.comp).
#define LANCER_ROWS_Photon(VEC4, VEC4S, SCALARS, UVEC4S)                  \
    VEC4(position)  /* xyz; w = its map: 0 caustic, 1 global */    \
    VEC4(direction) /* xyz = the way it travelled */               \
    VEC4(power)     /* rgb, watts */

// The photon pass's constants (a uniform block, written before each pass).
#define LANCER_ROWS_PhotonParams(VEC4, VEC4S, SCALARS, UVEC4S)                                                      \
    VEC4(radii) /* x, y = the caustic and global maps' gather radii this pass; z = the power quantum the gather sums in */ \
    SCALARS(uint, pass, uint, count, /* photons shot this pass */ uint, seed, uint, max_bounces)             \
    SCALARS(uint, capacity,   /* photons the photons array holds */                                          \
            uint, table_size, /* buckets per map of the hashed grid, a power of 2 */                         \
            uint, first_pass, uint, last_pass) /* the render's passes: [first_pass, last_pass) */

// Push constants of the grid build (shaders/photon_grid.comp): which step.
#define LANCER_ROWS_GridStep(VEC4, VEC4S, SCALARS, UVEC4S) \
    SCALARS(uint, kind, /* GRID_COUNT, ... */ uint, reserved0, uint, reserved1, uint, reserved2)

// Push constants: which band of rows this dispatch renders, and which of each pixel's N x N
// grid samples it traces, in the order a whole render traces them (k = j * N + i, row by row).
// A pass that does not start at sample 0 continues the sums the output buffer holds, and only
// the pass that ends at sample N * N divides by N * N: passes add the same floats in the same
// order as one full render, so progressive refinement ends on exactly that image.
// With refine_count > 0 the band is a compact list of pixels instead (adaptive anti-aliasing):
// the dispatch of `rows` rows has an invocation for each entry i < refine_count, workgroup by
// workgroup in order (entries [64 g, 64 g + 64) in workgroup g, counted row by row), which traces
// the pixel refine_list[refine_first + i] and writes pixels[i]; y0 is unused. Every lane but the last
// workgroup's tail has a pixel to trace. With spread = 1 it also writes the per-channel smallest and
// largest of the pixel's sample colours to pixels[refine_count + i] and pixels[2 refine_count + i]
// (adaptive anti-aliasing by the spread of a pixel's samples: render/adaptive_render.hpp).
// Workgroup g of the dispatch's G takes the place (tile, or run of list entries) of workgroup
// (g * group_stride) mod G in order: 1, or a stride coprime with G (gpu/tile_order.hpp).
#define LANCER_ROWS_BandParams(VEC4, VEC4S, SCALARS, UVEC4S)                      \
    SCALARS(uint, y0, uint, rows, uint, sample_first, uint, sample_count) \
    SCALARS(uint, refine_count, uint, spread, uint, refine_first, uint, group_stride)

// Push constants of the selection of pixels to refine (shaders/refine_select.comp).
#define LANCER_ROWS_SelectStep(VEC4, VEC4S, SCALARS, UVEC4S)                                                      \
    SCALARS(uint, kind,   /* SELECT_ENCODE, ... */                                                       \
            uint, width, uint, height,                                                                   \
            uint, every_candidate) /* 1: the threshold is 0 or less, every candidate goes on */         \
    SCALARS(uint, first,  /* SELECT_MERGE: the band's first entry in refine_list */                      \
            uint, count,  /* SELECT_MERGE: the band's entries */                                         \
            uint, spread, /* SELECT_MERGE: 1 when the band's output holds the samples' extremes; */      \
                          /* SELECT_FLAG: 1 when a candidate whose samples spread goes on */          \
            uint, reserved)

// The structs themselves, and their size in rows (Name_ROWS), from the lists above.
#define LANCER_MEMBER_VEC4(name) vec4 name;
#define LANCER_MEMBER_VEC4S(name, n) vec4 name[n];
#define LANCER_MEMBER_UVEC4S(name, n) uvec4 name[n];
#define LANCER_MEMBER_SCALARS(T0, n0, T1, n1, T2, n2, T3, n3) T0 n0; T1 n1; T2 n2; T3 n3;
#define LANCER_COUNT_VEC4(name) +1
#define LANCER_COUNT_VEC4S(name, n) +(n)
#define LANCER_COUNT_UVEC4S(name, n) +(n)
#define LANCER_COUNT_SCALARS(T0, n0, T1, n1, T2, n2, T3, n3) +1
#define LANCER_STRUCT(Name)                                                                      \
    struct Name {                                                                                \
        LANCER_ROWS_##Name(LANCER_MEMBER_VEC4, LANCER_MEMBER_VEC4S, LANCER_MEMBER_SCALARS, LANCER_MEMBER_UVEC4S) \
    };                                                                                           \
    LANCER_CONST Name##_ROWS = 0 LANCER_ROWS_##Name(LANCER_COUNT_VEC4, LANCER_COUNT_VEC4S, LANCER_COUNT_SCALARS, LANCER_COUNT_UVEC4S);

LANCER_STRUCT(Primitive)
LANCER_STRUCT(PatchLeaf)
LANCER_STRUCT(SurfaceInfo)
LANCER_STRUCT(ParametricCell)
LANCER_STRUCT(ImplicitInfo)
LANCER_STRUCT(ObjectFrame)
LANCER_STRUCT(CsgNode)
LANCER_STRUCT(MeshInfo)
LANCER_STRUCT(MeshNode)
LANCER_STRUCT(MeshTriangle)
LANCER_STRUCT(SetSphere)
LANCER_STRUCT(BlobElement)
LANCER_STRUCT(SorBand)
LANCER_STRUCT(PrismCurve)
LANCER_STRUCT(LatheBand)
LANCER_STRUCT(BvhNode)
LANCER_STRUCT(Material)
LANCER_STRUCT(TextureInfo)
LANCER_STRUCT(PatternInfo)
LANCER_STRUCT(Light)
LANCER_STRUCT(DirectionGrid)
LANCER_STRUCT(FrameParams)
LANCER_STRUCT(BandParams)
LANCER_STRUCT(Emitter)
LANCER_STRUCT(Photon)
LANCER_STRUCT(PhotonParams)
LANCER_STRUCT(GridStep)
LANCER_STRUCT(SelectStep)

// ---------------------------------------------------------------------------------------------
// Resources: every descriptor of set 0, as X(NAME, slot, kind, Element, member, reader, what).
//   NAME     BINDING_NAME is its binding; the shader's resource is named after it
//   slot     the binding number
//   kind     RESOURCE_UNIFORM: a uniform block holding one Element (per render)
//            RESOURCE_OUTPUT: a storage buffer of Elements the shader writes (the image band)
//            RESOURCE_ROWS: a uniform texel buffer (RGBA32UI) of Element structs, Element_ROWS
//              texels each, read with reader(i). llvmpipe turns a storage-buffer read into a
//              loop over the SIMD lanes (docs/performance.md); a texel fetch is a gather, ~3x
//              faster on a BVH, with no 64 KiB limit as uniform blocks have.
//            RESOURCE_UINT, RESOURCE_INT: a uniform texel buffer of 32-bit uints or ints (R32),
//              read by reader(i)
//   Element  the type of one element
//   member   the host's PackedScene array that fills it (host/gpu/packing/scene_packing.hpp), or the
//            block's member
//   reader   the GLSL function that reads element i
//   what     what its elements are, for messages ("the scene needs 2 GiB for its ...")
// ---------------------------------------------------------------------------------------------
LANCER_CONST RESOURCE_UNIFORM = 0;
LANCER_CONST RESOURCE_OUTPUT = 1;
LANCER_CONST RESOURCE_ROWS = 2;
LANCER_CONST RESOURCE_UINT = 3;
LANCER_CONST RESOURCE_INT = 4;

#define LANCER_SCENE_ARRAYS(X)                                                                          \
    X(PRIMITIVES, 1, RESOURCE_ROWS, Primitive, primitives, primitive_at, "primitives")                  \
    X(NODES, 2, RESOURCE_ROWS, BvhNode, nodes, node_at, "BVH nodes")                                    \
    X(MATERIALS, 3, RESOURCE_ROWS, Material, materials, material_at, "materials")                       \
    X(LIGHTS, 4, RESOURCE_ROWS, Light, lights, light_at, "lights")                                      \
    X(PATCHES, 5, RESOURCE_ROWS, PatchLeaf, patches, patch_leaf_at, "Bezier patch leaves")              \
    X(SURFACES, 6, RESOURCE_ROWS, SurfaceInfo, surfaces, surface_at, "parametric surfaces")             \
    X(CELLS, 7, RESOURCE_ROWS, ParametricCell, cells, cell_at, "parametric cells")                      \
    X(TEXTURES, 8, RESOURCE_ROWS, TextureInfo, textures, texture_at, "textures")                        \
    X(TEXELS, 9, RESOURCE_UINT, uint, texels, texel_at, "texture texels") /* RGBA8, R in the low byte */ \
    X(PATTERNS, 10, RESOURCE_ROWS, PatternInfo, patterns, pattern_at, "patterns")                       \
    X(PERMUTATION, 11, RESOURCE_INT, int, permutation, permutation_at, "noise permutation") /* Perlin's */ \
    X(IMPLICITS, 12, RESOURCE_ROWS, ImplicitInfo, implicits, implicit_at, "implicit surfaces")          \
    X(ENERGY, 13, RESOURCE_UINT, uint, energy_tables, energy_table_at, "microfacet energy tables") /* float bits */ \
    X(EMITTERS, 14, RESOURCE_ROWS, Emitter, emitters, emitter_at, "photon emitters")                   \
    X(OBJECT_FRAMES, 34, RESOURCE_ROWS, ObjectFrame, object_frames, object_frame_at, "object transforms") \
    X(CSG_NODES, 35, RESOURCE_ROWS, CsgNode, csg_nodes, csg_node_at, "CSG objects")                   \
    X(CSG_OPS, 36, RESOURCE_UINT, uint, csg_ops, csg_op_at, "CSG programs")                           \
    X(MESHES, 37, RESOURCE_ROWS, MeshInfo, meshes, mesh_at, "meshes")                                 \
    X(MESH_NODES, 38, RESOURCE_ROWS, MeshNode, mesh_nodes, mesh_node_at, "mesh tree nodes")            \
    X(MESH_TRIANGLES, 39, RESOURCE_ROWS, MeshTriangle, mesh_triangles, mesh_triangle_at, "mesh triangles") \
    X(MESH_MATERIALS, 40, RESOURCE_UINT, uint, mesh_materials, mesh_material_at, "mesh triangles' and set spheres' materials") \
    X(SET_SPHERES, 41, RESOURCE_ROWS, SetSphere, set_spheres, set_sphere_at, "sphere set spheres")     \
    X(BLOB_ELEMENTS, 42, RESOURCE_ROWS, BlobElement, blob_elements, blob_element_at, "blob components") \
    X(SOR_BANDS, 43, RESOURCE_ROWS, SorBand, sor_bands, sor_band_at, "sor segments")                   \
    X(PRISM_CURVES, 44, RESOURCE_ROWS, PrismCurve, prism_curves, prism_curve_at, "prism segments")     \
    X(LATHE_BANDS, 45, RESOURCE_ROWS, LatheBand, lathe_bands, lathe_band_at, "lathe segments")         \
    X(GRIDS, 31, RESOURCE_ROWS, DirectionGrid, grids, grid_at, "direction grids")                        \
    X(GRID_CELLS, 32, RESOURCE_UINT, uint, grid_cells, grid_cell_at, "direction grid cells")             \
    X(GRID_ENTRIES, 33, RESOURCE_UINT, uint, grid_entries, grid_entry_at, "direction grid entries") /* pairs: primitive, float bits of its nearest distance */

#define LANCER_RESOURCES(X)                                                          \
    X(FRAME, 0, RESOURCE_UNIFORM, FrameParams, frame, frame, "frame parameters")     \
    LANCER_SCENE_ARRAYS(X)                                                           \
    X(OUTPUT, 15, RESOURCE_OUTPUT, vec4, pixels, pixels, "output rows") /* one band of the image */  \
    X(REFINE, 16, RESOURCE_OUTPUT, uint, refine_list, refine_list, "pixels to refine") /* see BandParams */ \
    LANCER_PHOTON_BUFFERS(X)                                                         \
    LANCER_SELECT_BUFFERS(X)

// Photon mapping's working buffers, written by its compute passes (sizes: gpu/passes/photon_pass.cpp).
#define LANCER_PHOTON_BUFFERS(X)                                                                     \
    X(PHOTON_PARAMS, 17, RESOURCE_UNIFORM, PhotonParams, photon_params, photon_params, "photon pass parameters") \
    X(PHOTONS, 18, RESOURCE_OUTPUT, Photon, photons, photons, "photons")                             \
    X(PHOTONS_SORTED, 19, RESOURCE_OUTPUT, Photon, photons_sorted, photons_sorted, "photons by grid bucket") \
    X(PHOTON_COUNTER, 20, RESOURCE_OUTPUT, uint, photon_counter, photon_counter, "photon counter")   \
    X(CELL_COUNT, 21, RESOURCE_OUTPUT, uint, cell_count, cell_count, "photons per grid bucket")     \
    X(CELL_START, 22, RESOURCE_OUTPUT, uint, cell_start, cell_start, "grid bucket starts")          \
    /* the block totals of a prefix sum (shaders/block_scan.glsl), the grid's and the selection's */  \
    X(BLOCK_SUMS, 23, RESOURCE_OUTPUT, uint, block_sums, block_sums, "prefix sum block totals")      \
    /* the sorted photons and bucket starts again, as texel buffers for the tracer's gather (llvmpipe */ \
    /* reads storage buffers lane by lane): copied from the two above once a pass is sorted */            \
    X(GATHER_PHOTONS, 24, RESOURCE_ROWS, Photon, gather_photons, gather_photon_at, "photons to gather")   \
    X(GATHER_STARTS, 25, RESOURCE_UINT, uint, gather_starts, gather_start_at, "grid bucket starts to gather")

// Adaptive anti-aliasing's picture on the device, from which the selection (refine_select.comp)
// lists the pixels to refine into refine_list, with its count in block_sums (sizes:
// gpu/passes/refine_selection.cpp).
#define LANCER_SELECT_BUFFERS(X)                                                                       \
    X(PICTURE, 26, RESOURCE_OUTPUT, vec4, picture, picture, "adaptive picture") /* as pixels[] */       \
    X(PICTURE_CODES, 27, RESOURCE_OUTPUT, uint, picture_codes, picture_codes, "adaptive picture's sRGB codes") /* r | g << 8 | b << 16 */ \
    X(REFINE_FLAGS, 28, RESOURCE_OUTPUT, uint, refine_flags, refine_flags, "refinement flags") /* REFINE_* */ \
    X(SRGB_LEVELS, 29, RESOURCE_UINT, uint, srgb_levels, srgb_level_start, "sRGB level starts") /* float bits: image/difference_tables.hpp */ \
    X(DIFFERENCE_FLOORS, 30, RESOURCE_UINT, uint, difference_floors, blue_difference_floor, "colour difference floors") /* same */

#define LANCER_BINDING_CONSTANT(NAME, slot, kind, Element, member, reader, what) LANCER_CONST BINDING_##NAME = slot;
LANCER_RESOURCES(LANCER_BINDING_CONSTANT)

// ---------------------------------------------------------------------------------------------
// Specialisation constants, as X(NAME, id, type, member, default): the shader's `const type
// NAME`, the host's ShaderFeatures::member; type is bool or uint (a set of shape types, bit t
// for type t). Optional features are compiled out of scenes that lack them: lavapipe pays for
// dead code in register pressure (the unused Bezier clipper alone made a sphere scene ten times
// slower; docs/performance.md).
// ---------------------------------------------------------------------------------------------
#define LANCER_FEATURES(X)                                                                             \
    X(SCENE_SHAPES, 0, uint, scene_shapes, 0xffffffffu) /* the shape types the scene has (SCENE_HAS_<NAME>) */ \
    X(SCENE_HAS_BVH, 1, bool, has_bvh, true)                                                           \
    X(OUTPUT_HITS, 2, bool, output_hits, false)           /* test variant: write first hits, not colours */ \
    X(CHECK_LOOP_LIMIT, 3, bool, check_loop_limit, false) /* see loop_limit_reached (trace.comp) */      \
    X(SCENE_HAS_TEXTURES, 4, bool, has_textures, true)    /* some material has an image texture */      \
    X(SCENE_HAS_PATTERNS, 5, bool, has_patterns, true)    /* some material has a procedural pattern or bump */ \
    X(SCENE_HAS_TRANSPARENCY, 6, bool, has_transparency, true) /* transmission > 0: the ray tree, media */ \
    X(SCENE_HAS_AREA_LIGHTS, 7, bool, has_area_lights, true)                                           \
    X(SCENE_HAS_SPOT_LIGHTS, 8, bool, has_spot_lights, true)                                           \
    X(SCENE_HAS_FALLOFF, 9, bool, has_falloff, true)      /* a light with distance fall-off */          \
    X(SCENE_HAS_BLINN, 10, bool, has_blinn, true)         /* a material with highlight = "blinn" */     \
    X(SCENE_HAS_MICROFACET, 15, bool, has_microfacet, true) /* a material with model = "microfacet" */  \
    X(SCENE_HAS_PHOTONS, 16, bool, has_photons, true)     /* photon mapping: gather at diffuse hits */  \
    X(SCENE_HAS_RATIONAL_PATCHES, 17, bool, has_rational_patches, true) /* a Bezier leaf's weights not all 1 */ \
    X(BVH_HAS_ANALYTIC, 18, bool, bvh_has_analytic, true) /* a cheap bounded shape in the BVH; else all outside it */ \
    X(BOXED_FAMILIES, 19, uint, boxed_families, 0xffffffffu) /* families outside the BVH with a box (<NAME>_BOXED) */ \
    X(SPLIT_FAMILIES, 22, uint, split_families, 0xffffffffu) /* ... and with a box around each half (<NAME>_SPLIT) */ \
    X(DIRECTION_GRIDS, 25, bool, direction_grids, true)   /* camera and shadow rays through DirectionGrids, not the BVH */ \
    X(GRIDS_ONLY, 26, bool, grids_only, false)            /* every ray takes a grid: the BVH's traversal compiled out */ \
    X(CHECK_GRID_CONTRACT, 27, bool, check_grid_contract, false) /* tests: a ray without a grid under GRIDS_ONLY fails the render */ \
    X(SPHERES_BY_NEAR_POINTS, 28, bool, spheres_by_near_points, false) /* spheres packed by their points nearest the camera (sphere.glsl) */ \
    X(PLACED_OBJECTS, 29, bool, placed_objects, false) /* some object has a transform: patterns in object coordinates (placement.glsl) */ \
    X(OBJECT_SPACE_SHAPES, 30, bool, object_space_shapes, false) /* ... and some shape is traced in them */ \
    X(SCENE_HAS_FOG, 31, bool, has_fog, true) /* [fog]: every ray's segments fogged (trace.comp) */ \
    X(SCENE_HAS_SKY, 32, bool, has_sky, true) /* [sky]: rays that meet nothing see its ramp (trace.comp) */ \
    X(SKY_HAS_PATTERN, 33, bool, sky_has_pattern, true) /* ... or its pattern's colour at their direction */ \
    X(CSG_LEAF_SHAPES, 34, uint, csg_leaf_shapes, 0xffffffffu) /* the shape types of CSG leaves and their pieces (CSG_HAS_<NAME>) */ \
    X(LEAF_ONLY_SHAPES, 35, uint, leaf_only_shapes, 0u) /* ... of those, the types no primitive outside CSG has (TRACES_<NAME>) */ \
    X(LATHE_DEGREES, 36, uint, lathe_degrees, 0xffffffffu) /* bit n: some lathe is of degree n (lathe.glsl's searches) */

#ifdef __cplusplus
#define LANCER_ASSERT_SIZE(Name) static_assert(sizeof(Name) == 16 * Name##_ROWS, #Name " has padding");
LANCER_ASSERT_SIZE(Primitive)
LANCER_ASSERT_SIZE(PatchLeaf)
LANCER_ASSERT_SIZE(SurfaceInfo)
LANCER_ASSERT_SIZE(ParametricCell)
LANCER_ASSERT_SIZE(ImplicitInfo)
LANCER_ASSERT_SIZE(ObjectFrame)
LANCER_ASSERT_SIZE(CsgNode)
LANCER_ASSERT_SIZE(MeshInfo)
LANCER_ASSERT_SIZE(MeshNode)
LANCER_ASSERT_SIZE(MeshTriangle)
LANCER_ASSERT_SIZE(SetSphere)
LANCER_ASSERT_SIZE(BlobElement)
LANCER_ASSERT_SIZE(SorBand)
LANCER_ASSERT_SIZE(PrismCurve)
LANCER_ASSERT_SIZE(LatheBand)
LANCER_ASSERT_SIZE(BvhNode)
LANCER_ASSERT_SIZE(Material)
LANCER_ASSERT_SIZE(TextureInfo)
LANCER_ASSERT_SIZE(PatternInfo)
LANCER_ASSERT_SIZE(Light)
LANCER_ASSERT_SIZE(DirectionGrid)
LANCER_ASSERT_SIZE(FrameParams)
LANCER_ASSERT_SIZE(BandParams)
LANCER_ASSERT_SIZE(Emitter)
LANCER_ASSERT_SIZE(Photon)
LANCER_ASSERT_SIZE(PhotonParams)
LANCER_ASSERT_SIZE(GridStep)
LANCER_ASSERT_SIZE(SelectStep)
#undef LANCER_ASSERT_SIZE
}  // namespace lancer::gpu
#endif

#undef LANCER_CONST
#endif  // LANCER_LAYOUT_H

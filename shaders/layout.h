// The one definition of every GPU-visible struct, binding and enum.
//
// This header is compiled twice: by the C++ host (through host/gpu/layout.hpp) and by
// glslang as part of the compute shader (GL_GOOGLE_include_directive). Members are vec4s and
// 32-bit scalars only, so std430 (shader) and the C++ ABI agree without padding tricks; the
// host static_asserts the sizes and tests/unit/layout_reflection_test.cpp compares every
// offset with glslang's reflection of the compiled shader.
#ifndef LANCER_LAYOUT_H
#define LANCER_LAYOUT_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/vec4.hpp>
namespace lancer::gpu {
using vec4 = glm::vec4;
using uint = std::uint32_t;
#define LANCER_CONST constexpr uint
#else
#define LANCER_CONST const uint
#endif

// Descriptor bindings of set 0.
LANCER_CONST BINDING_FRAME = 0;       // uniform FrameParams
LANCER_CONST BINDING_PRIMITIVES = 1;  // buffer Primitive[]
LANCER_CONST BINDING_MATERIALS = 2;   // buffer Material[]
LANCER_CONST BINDING_LIGHTS = 3;      // buffer Light[]
LANCER_CONST BINDING_OUTPUT = 4;      // buffer vec4[] (one band of the image)
LANCER_CONST BINDING_NODES = 5;       // buffer BvhNode[]
LANCER_CONST BINDING_PATCHES = 6;     // buffer PatchLeaf[]
LANCER_CONST BINDING_SURFACES = 7;    // buffer SurfaceInfo[]
LANCER_CONST BINDING_CELLS = 8;       // buffer ParametricCell[]
LANCER_CONST BINDING_TEXTURES = 9;    // buffer TextureInfo[]
LANCER_CONST BINDING_TEXELS = 10;     // buffer uint[]: the RGBA8 texels of every texture, R in the low byte
LANCER_CONST BINDING_PATTERNS = 11;   // buffer PatternInfo[]
LANCER_CONST BINDING_PERMUTATION = 12;  // buffer int[256]: Ken Perlin's permutation, for noise.glsl

// Specialization constant ids (scene.glsl).
LANCER_CONST SPEC_HAS_BEZIER = 0;
LANCER_CONST SPEC_HAS_BVH = 1;
LANCER_CONST SPEC_OUTPUT_HITS = 2;  // debug/test variant: write first hits instead of colours
LANCER_CONST SPEC_CHECK_LOOP_LIMIT = 3;  // lavapipe: detect invocations its loop limit cut short (trace.comp)
// Optional shading features: compiled out of scenes that lack them (lavapipe pays for dead code).
LANCER_CONST SPEC_HAS_TEXTURES = 4;      // some material has an image texture
LANCER_CONST SPEC_HAS_PATTERNS = 5;      // some material has a procedural pattern or a bump
LANCER_CONST SPEC_HAS_TRANSPARENCY = 6;  // a material with transmission > 0: the ray tree, media, tinted shadows
LANCER_CONST SPEC_HAS_AREA_LIGHTS = 7;
LANCER_CONST SPEC_HAS_SPOT_LIGHTS = 8;
LANCER_CONST SPEC_HAS_FALLOFF = 9;       // a light with distance fall-off
LANCER_CONST SPEC_HAS_BLINN = 10;        // a material with highlight = "blinn"

// Workgroup shape: 8x8 = 64 invocations (lavapipe: 64-256 all within noise, 4x4 halves speed).
LANCER_CONST WORKGROUP_X = 8;
LANCER_CONST WORKGROUP_Y = 8;

// Primitive::type values. Each has one GLSL file in shaders/shapes/ and one C++ file in
// host/cpu/shapes/ with the same name.
LANCER_CONST SHAPE_SPHERE = 0;     // p0 = (center, radius), p1, p2 = the sphere's own x and y axes (its texture's frame)
LANCER_CONST SHAPE_PLANE = 1;      // p0 = (point, 0), p1 = (unit normal, 0), p2 = (texture u axis, 0)
LANCER_CONST SHAPE_RECTANGLE = 2;  // p0 = (corner, 0), p1 = (edge_u, 0), p2 = (edge_v, 0)
LANCER_CONST SHAPE_BOX = 3;        // p0 = (min, 0), p1 = (max, 0)
LANCER_CONST SHAPE_BEZIER = 4;     // data = index of its PatchLeaf
LANCER_CONST SHAPE_PARAMETRIC = 5; // data = index of its ParametricCell, p0 = (box min, 0), p1 = (box max, 0)
LANCER_CONST SHAPE_IMPLICIT = 6;   // data = index of its SurfaceInfo, p0 = (box min, 0), p1 = (box max, 0) in its own coordinates

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

// Light::type values.
LANCER_CONST LIGHT_POINT = 0;
LANCER_CONST LIGHT_SPOT = 1;
LANCER_CONST LIGHT_AREA = 2;

struct Primitive {
    uint type;
    uint material;
    uint data;    // shape-specific index into a further buffer (patch shapes), else 0
    uint object;  // index of the scene object it came from
    vec4 p0;
    vec4 p1;
    vec4 p2;
};

// A bicubic (rational) Bezier sub-patch, ready for Bezier clipping. Control points are stored
// relative to `origin` (the leaf's centre) so that float keeps its precision far from the
// world origin.
struct PatchLeaf {
    vec4 points[16];  // xyz = control point - origin, w = weight (1 for polynomial patches); row-major, i along u
    vec4 origin;      // xyz; w = index of the patch within its surface (for tests and texture lookups)
    vec4 domain;      // (u0, u1, v0, v1): where this leaf lies in its patch's parameter square
};

// Per expression surface, so moving an object only rewrites this buffer, never the generated
// shader code. A parametric surface: the affine map from the user's (x, y, z) to world space,
// world = (dot(row0.xyz, p) + row0.w, dot(row1.xyz, p) + row1.w, dot(row2.xyz, p) + row2.w).
// An implicit surface: the inverse map, from world space to the coordinates f is written in.
struct SurfaceInfo {
    vec4 row0;
    vec4 row1;
    vec4 row2;
    vec4 domain;  // parametric: (u0, u1, v0, v1) of the whole surface; implicit: unused
};

// One cell of a parametric surface's domain: where Newton's method looks for roots. The corner
// points give Newton a starting point near the root (where the ray meets the two triangles they
// span), so one or two seeds suffice instead of a grid of them.
struct ParametricCell {
    vec4 domain;  // (u0, u1, v0, v1)
    vec4 p00;     // xyz = S(u0, v0) in world space; w = the surface index (its generated function)
    vec4 p10;     // S(u1, v0)
    vec4 p01;     // S(u0, v1)
    vec4 p11;     // S(u1, v1)
};

// A node of the bounding volume hierarchy over all bounded primitives (host/accel/bvh.hpp).
// Inner nodes (count == 0) have their children at first and first + 1; leaves cover the
// primitives [first, first + count). Boxes are rounded outward from double.
struct BvhNode {
    vec4 lo;  // xyz
    vec4 hi;  // xyz
    uint first;
    uint count;
    uint reserved0;
    uint reserved1;
};

struct Material {
    vec4 color;    // rgb = pigment (checker: first colour), linear
    vec4 color2;   // rgb = second checker colour
    vec4 phong;    // x = ambient, y = diffuse, z = specular, w = shininess (n_s)
    float reflection;
    uint pattern;
    float checker_size;
    uint reserved;
    // textures and patterns (shaders/appearance.glsl): indices, or NO_MAP
    uint texture_map;    // into textures[]: the pigment is multiplied by the image's colour
    uint color_pattern;  // into patterns[]: the pigment is multiplied by the pattern's colour
    uint bump_pattern;   // into patterns[]: the shading normal is tilted by the pattern's gradient
    uint maps_reserved;

    // optics: refraction and the highlight model
    vec4 transmission;  // rgb = T, the fraction passed per channel (all 0: opaque); w = ior
    vec4 absorption;    // rgb = Beer-Lambert coefficient per unit distance inside; w unused
    uint highlight;     // HIGHLIGHT_PHONG or HIGHLIGHT_BLINN
    uint optics_reserved0;
    uint optics_reserved1;
    uint optics_reserved2;
};

// An image as a material places it (shaders/texture.glsl). Image coordinates (s, t) run from
// (0, 0) at the image's bottom-left corner to (1, 1) at its top-right one.
struct TextureInfo {
    vec4 to_image_s;  // s = dot(xy, uv) + z, uv the surface's texture coordinates
    vec4 to_image_t;  // t = dot(xy, uv) + z
    uint texel_offset;  // its first texel in texels[]; rows from the top
    uint width;
    uint height;
    uint flags;       // TEXTURE_CLAMP_U | TEXTURE_CLAMP_V | TEXTURE_NEAREST
};

// A procedural pattern (shaders/pattern.glsl): a scalar function of the world position, shown
// through a colour ramp or used as a bump.
struct PatternInfo {
    vec4 row0;    // world -> pattern space: q = (dot(row0.xyz, p) + row0.w, dot(row1..), dot(row2..))
    vec4 row1;
    vec4 row2;
    vec4 params;  // x = turbulence, y = omega, z = lambda, w = bump strength (amount x mean scale)
    uint type;    // PATTERN_NOISE, ...
    uint octaves;
    uint color_count;
    uint reserved;
    vec4 colors[PATTERN_MAX_COLORS];  // rgb = colour, w = its position on the ramp, ascending
};

struct Light {
    vec4 position;   // xyz = where it is (area light: the rectangle's centre); w = fall-off distance, 0 = none
    vec4 color;      // rgb
    vec4 direction;  // spot: xyz = unit axis of the cone
    vec4 spot;       // spot: x = cos(outer_angle), y = cos(inner_angle), z = tightness
    vec4 edge_u;     // area: xyz = first edge (whole length)
    vec4 edge_v;     // area: xyz = second edge
    uint type;       // LIGHT_POINT, LIGHT_SPOT or LIGHT_AREA
    uint samples;    // area: n, for n x n shadow samples
    uint jitter;     // area: 1 = each sample at a hashed place in its cell, 0 = at the cell's centre
    uint reserved;
};

// Per-render constants (a uniform buffer). The camera is given as the vectors from which the
// shader forms ray directions: dir = forward + ndc_x * right + ndc_y * up, with ndc in [-1, 1].
struct FrameParams {
    vec4 eye;
    vec4 forward;
    vec4 right;       // already scaled by tan(fov/2) * aspect
    vec4 up;          // already scaled by tan(fov/2)
    vec4 background;  // rgb
    vec4 ambient;     // rgb, the scene's ambient light
    uint width;
    uint height;
    uint samples;     // N: an N x N grid of rays per pixel
    uint max_depth;   // reflection bounces after the camera ray
    uint primitive_count;  // all primitives: the BVH's, then the unbounded ones (planes)
    uint light_count;
    uint node_count;       // 0 when nothing is bounded
    uint unbounded_count;  // the last unbounded_count primitives are tested by every ray
    uint loop_probe;       // always 2: the trip count of trace.comp's loop_limit_reached() probe
    uint reserved0;
    uint reserved1;
    uint reserved2;
};

// Push constants: which band of rows this dispatch renders, and which of each pixel's N x N
// grid samples it traces, in the order a whole render traces them (k = j * N + i, row by row).
// A pass that does not start at sample 0 continues the sums the output buffer holds, and only
// the pass that ends at sample N * N divides by N * N: passes add the same floats in the same
// order as one full render, so progressive refinement ends on exactly that image.
struct BandParams {
    uint y0;
    uint rows;
    uint sample_first;
    uint sample_count;
};

#ifdef __cplusplus
static_assert(sizeof(Primitive) == 64);
static_assert(sizeof(Material) == 128);
static_assert(sizeof(TextureInfo) == 48);
static_assert(sizeof(PatternInfo) == 208);
static_assert(sizeof(Light) == 112);
static_assert(sizeof(BvhNode) == 48);
static_assert(sizeof(PatchLeaf) == 288);
static_assert(sizeof(SurfaceInfo) == 64);
static_assert(sizeof(ParametricCell) == 80);
static_assert(sizeof(FrameParams) == 144);
static_assert(sizeof(BandParams) == 16);
}  // namespace lancer::gpu
#endif

#undef LANCER_CONST
#endif  // LANCER_LAYOUT_H

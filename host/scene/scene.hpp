#pragma once
// The scene model: what a scene file describes, independent of how it is rendered.
// Both renderers (cpu/, gpu/) read this; it knows about neither of them.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/error.hpp"
#include "core/heap_optional.hpp"
#include "core/heap_value.hpp"
#include "core/rare_string.hpp"
#include "image/tone.hpp"
#include "optics/metals.hpp"
#include "mesh/mesh_geometry.hpp"
#include "mesh/element_tree.hpp"
#include "mesh/sphere_cloud.hpp"
#include "scene/material_maps.hpp"
#include "shapes.h"  // the shape registry
#include "surface/bezier_patch.hpp"
#include "surface/implicit_surface.hpp"
#include "surface/parametric_surface.hpp"

namespace lancer {

using glm::dvec3;

// What makes adaptive anti-aliasing refine a pixel again after a grid (after its first ray it is
// always judged by its neighbours): its colour against its neighbours' (POV-Ray's +AM1), or
// that and also the spread of its own samples (as POV-Ray's +AM2 judges a pixel by its corners).
enum class AaMethod { Neighbours, Spread };

struct RenderSettings {
    int width = 640;
    int height = 480;
    int samples = 3;    // an N x N grid of rays per pixel (with aa_threshold: the most a pixel gets)
    // Adaptive anti-aliasing (render/adaptive_render.hpp): one ray per pixel, then finer grids
    // up to N x N for the pixels whose colour differs by more than this (|dr| + |dg| + |db|,
    // sRGB colours in 0..1; 0 refines every pixel) from a neighbour's or, with AaMethod::Spread,
    // also among the pixel's own samples. Unset: every pixel gets the full grid.
    std::optional<double> aa_threshold;
    int aa_depth = 1;  // refinements: grids 1 x 1, ..., N x N (1: straight to N x N, POV-Ray's +AM1)
    AaMethod aa_method = AaMethod::Neighbours;
    int max_depth = 5;  // levels of reflection and refraction after the camera ray
    dvec3 background{0.0, 0.0, 0.0};
    // How linear radiance becomes the PNG's 8 bits (image/tone.hpp): exposure in stops, tone curve.
    ToneMapping tone;
};

// Photon mapping ([photons]; docs/scene-format.md): passes of `count` photons each, whose
// estimates are averaged with radii shrinking pass by pass (Knaus and Zwicker's progressive
// photon mapping), so the image converges as passes are added.
struct PhotonSettings {
    int count = 100000;           // photons shot from the lights per pass
    int passes = 16;              // K
    double caustic_radius = 0.0;  // the first pass's gather radius for the caustic map
    double global_radius = 0.0;   // and for the global (indirect diffuse) map
    double alpha = 0.7;           // r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1)
    std::uint32_t seed = 0;
    int max_bounces = 16;         // interactions of a photon path, Russian roulette aside
    // Passes [first_pass, first_pass + pass_count) of the K (a farm renders parts of a still).
    int first_pass = 0;
    int pass_count = 0;  // 0: all K

    int last_pass() const { return pass_count ? first_pass + pass_count : passes; }  // one past
};

// The gather radius of pass k (from 0): r_k^2 = r_0^2 prod_{i=1..k} (i - 1 + alpha) / i.
double photon_radius(double first_radius, double alpha, int pass);

struct CameraSpec {
    dvec3 eye{0.0, 0.0, -5.0};
    dvec3 look_at{0.0, 0.0, 0.0};
    dvec3 up{0.0, 1.0, 0.0};
    double fov_deg = 60.0;  // vertical field of view
};

enum class LightType {
    Point,  // all directions from `position`
    Spot,   // a cone from `position` around `direction`
    Area,   // a rectangle centred on `position`, sampled n x n for soft shadows
};

enum class Falloff {
    None,           // the same intensity at every distance
    InverseSquare,  // color * (falloff_distance / d)^2
    PovFade,        // POV-Ray's fade: color * 2 / (1 + (d / falloff_distance)^fade_power)
};

// A light ([[light]]). Every type has position, color, name and the distance fall-off; the
// other members belong to one type (docs/scene-format.md, "[[light]]").
struct Light {
    LightType type = LightType::Point;
    dvec3 position{0.0};  // point and spot: where it is; area: the centre of its rectangle
    dvec3 color{1.0};     // with fall-off: the intensity at falloff_distance (times `scale`)
    // Lights given in watts (power or intensity) keep `color` as a tint and carry their size
    // here, so that colour keyframes stay tints: what the renderers use is emitted().
    double scale = 1.0;
    std::string name;     // optional, for [animation] to refer to it
    Falloff falloff = Falloff::None;
    double falloff_distance = 1.0;
    double fade_power = 0.0;  // PovFade: POV-Ray's fade_power (any positive value)
    SourceLocation where;  // the [[light]] table, for messages

    // Spot (POV-Ray's spotlight): full intensity within inner_angle of the axis, none beyond
    // outer_angle, a smooth cubic between; times cos(angle)^tightness.
    dvec3 direction{0.0, -1.0, 0.0};  // unit axis of the cone
    std::optional<dvec3> point_at;    // when given, the spot keeps aiming at it as it moves
    double inner_angle_deg = 30.0;
    double outer_angle_deg = 45.0;
    double tightness = 0.0;

    // Area: the rectangle position + a * edge_u + b * edge_v, a, b in [-1/2, 1/2], seen from a
    // shading point as samples x samples point lights of color / samples^2 each.
    dvec3 edge_u{0.0};
    dvec3 edge_v{0.0};
    int samples = 4;
    bool jitter = true;  // each sample at a hashed place within its cell, else at the cell's centre

    // The colour the shading model uses: the light seen at falloff_distance (scene-format.md).
    dvec3 emitted() const { return color * scale; }
};

// Points a spot light with point_at at it again (after its position moved); other lights and
// spots given a fixed direction are left as they are.
void aim_spot(Light& light);

// A light's radiant flux in watts per channel, where its colour is in the renderer's radiance
// units (one unit of `color` at falloff_distance d0 is an intensity of pi d0^2 W/sr: the
// irradiance pi at d0 that makes a white diffuse surface's radiance 1). Lights without fall-off
// would have infinite power: nullopt.
std::optional<dvec3> radiant_flux(const Light& light);

// The solid angle a spot light's cone covers, weighted by its spot factor (steradians): its
// intensity on the axis times this is its power.
double spot_solid_angle(const Light& light);

struct Checker {
    dvec3 color_a{1.0};  // where floor(x/s)+floor(y/s)+floor(z/s) is even
    dvec3 color_b{0.0};
    double size = 1.0;
    // Its own `transform` (POV-Ray's pigment { checker ... scale, rotate }), inverted: from the
    // object's coordinates into the checker's. None: the object's coordinates are the checker's.
    std::optional<glm::dmat4> to_checker;
};

enum class Highlight {
    Phong,  // k_s * (R.L)^n_s, R the mirrored view ray
    Blinn,  // k_s * (N.H)^n_s, H the unit half vector between L and the view direction
};

enum class Model {
    Phong,       // ambient, diffuse, highlight and mirror terms (POV-Ray's finish)
    Microfacet,  // GGX microfacets with exact Fresnel: a metal or a glass (docs/scene-format.md)
};

// A material: Phong (the default, with POV-Ray's finish defaults, so ported scenes look the same)
// or microfacet.
struct Material {
    std::string name;
    dvec3 color{1.0};
    std::optional<Checker> checker;
    double ambient = 0.1;
    double diffuse = 0.6;
    double specular = 0.0;   // POV-Ray: phong
    double shininess = 40.0; // POV-Ray: phong_size
    double reflection = 0.0;
    // textures and patterns: the pigment is color x texture x pattern; bump tilts the normal
    std::optional<ImageTexture> texture;
    std::optional<Pattern> pattern;
    std::optional<Bump> bump;

    // Optics: refraction and the highlight model (docs/scene-format.md, "Refraction").
    dvec3 transmission{0.0};  // T per channel: 0 is opaque; above 0 the surfaces bound a dielectric
    double ior = 1.0;         // index of refraction of the inside
    dvec3 absorption{0.0};    // Beer-Lambert coefficient per unit distance inside
    Highlight highlight = Highlight::Phong;

    // The microfacet model: a metal (conductor set) or a glass (transparent). `color` tints it.
    Model model = Model::Phong;
    double roughness = 0.0;  // 0: a perfect mirror or perfectly smooth glass; GGX alpha = roughness^2
    std::optional<optics::ComplexIor> conductor;

    bool microfacet() const { return model == Model::Microfacet; }
    double alpha() const { return roughness * roughness; }
    bool transparent() const { return transmission.r > 0.0 || transmission.g > 0.0 || transmission.b > 0.0; }
    // Whether a hit on it traces further rays (a mirror ray, a refracted one, a microfacet
    // lobe's): where none but one flat mirror does, every ray of the GPU's tracer can take a
    // direction grid (gpu/packing/acceleration_plan.hpp), and the CPU reference's path ends.
    bool spawns_secondary_rays() const { return reflection > 0.0 || transparent() || microfacet(); }
};

struct Sphere {
    dvec3 center{0.0};
    double radius = 1.0;
    // Sphere space -> world (a rotation): only where its texture lies. Texture (u, v) come from
    // the direction from the centre in sphere space (docs/scene-format.md).
    glm::dmat3 orientation{1.0};
};

struct Plane {
    dvec3 point{0.0};
    dvec3 normal{0.0, 1.0, 0.0};  // unit length
    // Texture (u, v) = ((p - point).u_axis, (p - point).v_axis): unit vectors in the plane,
    // v_axis along the world's up (+z for a horizontal plane), u_axis = normal x v_axis.
    dvec3 u_axis{1.0, 0.0, 0.0};
    dvec3 v_axis{0.0, 0.0, 1.0};
};

// A parallelogram: corner + a * edge_u + b * edge_v for a, b in [0, 1].
struct Rectangle {
    dvec3 corner{0.0};
    dvec3 edge_u{1.0, 0.0, 0.0};
    dvec3 edge_v{0.0, 0.0, 1.0};
};

// Axis-aligned box.
struct Box {
    dvec3 min{-1.0};
    dvec3 max{1.0};
};

// A set of bicubic (rational) Bezier patches, in world space (a transform is applied to the
// control points when the scene is loaded: exact for affine maps).
struct BezierSurface {
    std::vector<surface::BezierPatch> patches;
    int subdivision = 1;      // the GPU splits each patch into 2^n x 2^n leaves (tighter boxes)
    std::string source_file;  // the patch file they came from, if any
    int outward = 0;          // declared closed: +1 where S_u x S_v points out of the solid, -1 where in; else 0
};

// A surface given by its equations, with a world box proved to contain it (interval arithmetic
// over the cells of its domain: surface/parametric_cells.hpp). The GPU cuts it into its own cells
// when it packs the scene; renderers need nothing else from the loader.
struct ParametricObject {
    HeapValue<surface::ParametricSurface> surface;  // on the heap: the variant stays a sphere's size
    dvec3 bounds_lo{0.0}, bounds_hi{0.0};  // world space
    int outward = 0;  // declared closed: +1 where S_u x S_v points out of the solid, -1 where in; else 0
};

// A surface given by its equation f(x, y, z) = 0, clipped to a box (docs/scene-format.md).
struct ImplicitObject {
    HeapValue<surface::ImplicitSurface> surface;  // on the heap: the variant stays a sphere's size
};

// POV-Ray's disc: the points of the plane through `center` with unit `normal` whose distance r
// from the centre has hole_radius <= r <= radius (0 <= hole_radius < radius). A thin sheet, no
// inside. Texture (u, v) are polar: u the angle about the normal from u_axis toward v_axis (the
// plane's texture axes for that normal, set_plane_texture_axes) over 2 pi, v = (r - hole_radius)
// / (radius - hole_radius) (docs/scene-format.md).
struct Disc {
    dvec3 center{0.0};
    dvec3 normal{0.0, 1.0, 0.0};  // unit length
    double radius = 1.0;
    double hole_radius = 0.0;
    dvec3 u_axis{1.0, 0.0, 0.0};
    dvec3 v_axis{0.0, 0.0, 1.0};
};

// POV-Ray's cone and cylinder (one shape): the surface of revolution about the segment from
// `base` to `cap` whose radius runs linearly from base_radius at the base to cap_radius at the
// cap (equal for a cylinder; one of them may be 0, a pointed cone), closed by a disc across the
// axis at each end of non-zero radius unless `open` (a tube: POV-Ray's `open`). Texture (u, v):
// u the angle about the axis from u_axis toward v_axis (the plane's texture axes for the unit
// axis as its normal, set_plane_texture_axes) over 2 pi; on the side v runs from 0 at the base
// to 1 at the cap, on each end disc from 0 at its centre to 1 at its rim (docs/scene-format.md).
struct Cone {
    dvec3 base{0.0};
    dvec3 cap{0.0, 1.0, 0.0};  // |cap - base| > 0
    double base_radius = 1.0;  // >= 0, not both 0
    double cap_radius = 1.0;
    bool open = false;
    dvec3 u_axis{1.0, 0.0, 0.0};
    dvec3 v_axis{0.0, 0.0, 1.0};
};

// POV-Ray's torus: the points at distance minor_radius from the circle of radius major_radius
// about `center` across the unit `axis` (POV-Ray's lies in the XZ plane around +y), the quartic
// (|p|^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2) in its own frame (y along the axis). With r > R (a
// spindle torus) the quartic is the whole self-intersecting surface, the outer "apple" and the
// inner "lemon", and its inside (f < 0) the apple less the lemon: POV-Ray's `difference` spindle
// mode. Texture (u, v): u the angle about the axis from u_axis toward v_axis (the plane's texture
// axes for that normal) over 2 pi, v the angle around the tube from its outer equator toward
// +axis over 2 pi, both in [0, 1) (docs/scene-format.md).
struct Torus {
    dvec3 center{0.0};
    dvec3 axis{0.0, 1.0, 0.0};  // unit length
    double major_radius = 1.0;
    double minor_radius = 0.25;
    dvec3 u_axis{1.0, 0.0, 0.0};
    dvec3 v_axis{0.0, 0.0, 1.0};
};

// A triangle mesh read from a file (docs/scene-format.md, "Meshes"): the file's triangles, in its
// own coordinates, shared by every object placed from the same file. A mesh object is always
// placed (its Placement, the identity where it has no transform), so that both renderers trace
// every placement through one copy of the triangles. Triangles are exact and watertight on both
// backends; `smooth` interpolates the vertex normals for shading (the file's, or computed where
// it has none). Texture (u, v): the file's, interpolated; where it has none, the hit's
// barycentric coordinates.
struct Mesh {
    std::shared_ptr<const MeshGeometry> geometry;
    bool smooth = false;
    std::string source_file;
    // Where the object takes its file's materials (an OBJ's MTL; the object, its group and its
    // placement name none): the scene material of each of the file's, else empty (the object's
    // material everywhere).
    std::vector<std::uint32_t> part_materials;
    int outward = 0;  // a CSG operand: +1 where the triangles' fronts face out of the solid, -1 where in; else 0

    // The material of triangle `triangle`, `object_material` unless the file's apply.
    std::uint32_t material_of(std::size_t triangle, std::uint32_t object_material) const {
        if (part_materials.empty()) return object_material;
        return part_materials[geometry->mesh().triangle_materials[triangle]];
    }
};

// POV-Ray users' many spheres (docs/scene-format.md, "Sphere sets"): a PLY point set's spheres,
// in its own coordinates, shared by every object placed from the same file, traced through its
// own tree as a mesh's triangles are. Always placed, as a mesh. Each sphere's (u, v) is a
// sphere's, about its centre along the set's axes.
struct SphereSet {
    std::shared_ptr<const SphereCloud> cloud;
    std::string source_file;
    // Where the file has colours: the scene material of each palette colour (the object's, its
    // colour the point's); else empty.
    std::vector<std::uint32_t> part_materials;

    std::uint32_t material_of(std::size_t sphere, std::uint32_t object_material) const {
        if (part_materials.empty()) return object_material;
        return part_materials[cloud->colors()[sphere]];
    }
};

// POV-Ray's blob (docs/scene-format.md): the field of each component is
// strength (1 - d^2 / radius^2)^2 within radius of its centre (a sphere: a == b) or of its segment
// from a to b (a cylinder with round ends, as POV-Ray's), 0 beyond. The surface is where the
// fields' sum is the threshold; its inside (f = threshold - field < 0) where the sum is more.
// Along a ray each component's field is a quartic in t between the points where the ray enters
// or leaves it or crosses its segment's end planes: the surface's roots are exact, interval by
// interval (cpu/shapes/blob.cpp, shaders/shapes/blob.glsl). Texture (u, v): the hit's x and y
// across the box, as an implicit surface's.
struct BlobComponent {
    dvec3 a{0.0}, b{0.0};
    double radius = 1.0;
    double strength = 1.0;
    bool is_sphere() const { return a == b; }
};
struct Blob {
    double threshold = 0.5;
    std::vector<BlobComponent> components;
    // Set by prepare_blob (shape_bounds.hpp) whenever the components change:
    dvec3 lo{0.0}, hi{0.0};  // the box of the components of positive strength: the surface is inside it
    std::shared_ptr<const ElementTree> tree;  // over the components' boxes (the CPU reference's own)
};

// POV-Ray's surface of revolution (sor): about the y axis of its own coordinates, its radius
// squared a cubic in y on each segment, r^2 = ((a u + b) u + c) u + d with u = y - y0 (the
// segment's own coefficients about its bottom, for precision), through the squared radii of
// POV-Ray's points 1 .. n-2 with POV-Ray's slopes, 2 r_j (r_{j+1} - r_{j-1}) / (y_{j+1} - y_{j-1})
// (points 0 and n-1 give only the end slopes). Closed by discs at its bottom and top (the base and the cap) unless `open`; its inside
// (x^2 + z^2 < r^2(y) between them) makes it a solid for CSG, refraction and photons where it is
// closed. A segment where the spline dips below 0 has no surface there. Texture (u, v): u the
// angle about y from +x toward +z over 2 pi, v the height from bottom to top in [0, 1] (the
// discs' v is 0 and 1).
struct SorSegment {
    double y0 = 0.0, y1 = 1.0;            // the segment's heights, y0 < y1
    double a = 0.0, b = 0.0, c = 0.0, d = 1.0;  // r^2 about y0
    double r_max = 1.0;                   // the largest radius on the segment (its bounding cylinder)
};
struct Sor {
    std::vector<SorSegment> segments;  // in order of height, each starting where the last ends
    bool open = false;
    double base_r2 = 1.0, cap_r2 = 1.0;  // the discs' squared radii: POV-Ray's points 1 and n-2's
    double r_max = 1.0;                  // the largest radius of all
};

// POV-Ray's prism: an outline in the x-z plane of its own coordinates, extruded along y between y0
// and y1 (linear sweep) or, with `conic`, its copies scaled by y about the y axis (the outline at
// y = 1, the apex at the origin: POV-Ray's conic_sweep, y0 and y1 on one side of 0), closed by
// caps there unless `open` (a conic sweep's end at its apex has none). The outline is closed contours
// of 2-D Bezier segments (POV-Ray's linear, quadratic, cubic and Bezier splines all convert
// exactly); inside is the even-odd rule over all of them (nested contours make holes), which makes
// a closed prism a solid for CSG, refraction and photons. Built by make_prism (scene/prism.hpp),
// for the reader and for anything else that makes outlines. Texture (u, v): (x, z).
struct PrismSegment {
    int degree = 1;                      // 1, 2 or 3
    std::array<glm::dvec2, 4> p{};       // control points (x, z), p[0] .. p[degree]
    glm::dvec2 start() const { return p[0]; }
    glm::dvec2 end() const { return p[static_cast<std::size_t>(degree)]; }
};
struct Prism {
    std::vector<PrismSegment> segments;  // closed contours, one after another: each segment starts where the last ended
    double y0 = 0.0, y1 = 1.0;           // the heights, y0 < y1
    bool open = false;
    bool conic = false;                  // POV-Ray's conic_sweep
    // Set by prepare_prism (scene/prism.hpp) whenever the segments change:
    glm::dvec2 lo{0.0}, hi{0.0};               // the outline's box (its control points')
    std::shared_ptr<const ElementTree> tree;  // over the segments' boxes (the CPU reference's own)
};

// POV-Ray's lathe: a 2-D spline in the (r, y) plane turned about the y axis of its own
// coordinates. Each segment is a Bezier curve of the lathe's degree (1: linear_spline, 2:
// quadratic_spline, 3: cubic_spline and bezier_spline), its control points (r[i], y[i]) for
// i = 0 .. degree in s in [0, 1]: every POV-Ray spline piece is exactly one (parse_lathe.cpp).
// The curve's radius stays >= 0 (the reader refuses one that dips below the axis). The lathe is
// `closed` where the curve ends where it starts or both its ends lie on the axis: then its
// inside is POV-Ray's even-odd rule (a point is inside where a half-line from it away from the
// axis at its height crosses the curve an odd number of times), and it is a solid for CSG,
// refraction and photons; an open one has no inside. `side` says which way each segment's
// outward normal faces: +1 (y'(s), -r'(s)) in the (r, y) plane, -1 the opposite. Texture (u, v):
// u the angle about y from +x toward +z over 2 pi, v POV-Ray's (segment + s) / segment count.
struct LatheSegment {
    std::array<double, 4> r{}, y{};  // the Bezier control points, degree + 1 of them
    double r_max = 0.0;              // the largest control radius (the curve's bounding cylinder)
    double y_lo = 0.0, y_hi = 0.0;   // the lowest and highest control heights
    int side = 1;
};
struct Lathe {
    int degree = 1;
    std::vector<LatheSegment> segments;  // in the spline's order
    bool closed = true;
    double r_max = 0.0, y_lo = 0.0, y_hi = 0.0;  // over every segment
};

// POV-Ray's superellipsoid { <e, n> }: g(x, y, z) = (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) <= 1,
// in [-1, 1]^3 of its own coordinates (it is always placed), e and n in [0.001, 2]. There the
// exponents p = 2/e and q = 2/n are at least 1, so F = g^(1/q), the q-norm of (the p-norm of
// (x, y), z), is a norm: the solid F <= 1 is convex (a solid for CSG: its inside along a line is
// one interval) and F along a ray is convex. Texture (u, v): x and y across the box [-1.01, 1.01]^2
// ((x + 1.01) / 2.02, (y + 1.01) / 2.02), as when it was drawn as an implicit surface in that box.
struct Superellipsoid {
    double e = 1.0, n = 1.0;
};

struct Object;

// Constructive solid geometry: POV-Ray's intersection, difference and merge (docs/scene-format.md,
// "CSG"). `leaves` are solids (shapes with SHAPE_SOLID: convex and closed, or half-spaces; or
// with SHAPE_CLOSED: a torus, an implicit surface proved closed in its box; or with SHAPE_ORIENTED:
// a parametric or Bezier surface declared and checked closed), each
// an object with its own placement and material; `program` combines whether a point is inside
// each (postfix: the CSG_* ops of shapes.h). The surface is where the combination's value changes
// along a ray; each of its points is a leaf's, shaded with that leaf's material and texture.
struct Csg {
    std::vector<Object> leaves;
    std::vector<std::uint32_t> program;
    dvec3 lo{0.0}, hi{0.0};  // the world box the combination lies in
};

using Shape = std::variant<Sphere, Plane, Rectangle, Box, BezierSurface, ParametricObject, ImplicitObject, Disc, Cone, Torus, Csg, Mesh,
                           SphereSet, Blob, Sor, Prism, Lathe, Superellipsoid>;

// The alternatives of Shape are the shape registry's rows, in order: index() is the shape type.
#define LANCER_SHAPE_ALTERNATIVE(NAME, name, Type, type, traits) \
    static_assert(std::is_same_v<std::variant_alternative_t<type, Shape>, Type>, "Shape's order is shapes.h's");
LANCER_SHAPES(LANCER_SHAPE_ALTERNATIVE)
#undef LANCER_SHAPE_ALTERNATIVE
static_assert(std::variant_size_v<Shape> == SHAPE_COUNT);
inline std::uint32_t shape_type(const Shape& shape) { return static_cast<std::uint32_t>(shape.index()); }

// A surface that closes a solid (SHAPE_ORIENTED: a Bezier or parametric surface declared closed,
// a mesh in CSG): +1 where its normals point out of the solid, -1 where in; 0 for any other shape
// or one not known to be closed.
inline int outward_side(const Shape& shape) {
    if (const auto* b = std::get_if<BezierSurface>(&shape)) return b->outward;
    if (const auto* p = std::get_if<ParametricObject>(&shape)) return p->outward;
    if (const auto* m = std::get_if<Mesh>(&shape)) return m->outward;
    return 0;
}

// Where an object's `transform` put it (docs/scene-format.md, "Transforms"). Patterns and
// checkers are evaluated at the object's own coordinates, so they move with it (POV-Ray's rule).
// A shape whose family the transform keeps (a sphere moved, turned and scaled alike on every
// axis; a rectangle under any affine map; ...) is stored with the transform applied; the others
// (an ellipsoid, a turned box) keep their own coordinates, and the renderers carry rays into them.
struct Placement {
    glm::dmat4 to_world{1.0};   // object -> world
    glm::dmat4 to_object{1.0};  // its inverse
    bool shape_in_object_space = false;

    dvec3 object_point(const dvec3& p) const { return dvec3(to_object * glm::dvec4(p, 1.0)); }
    dvec3 object_direction(const dvec3& d) const { return glm::dmat3(to_object) * d; }
    // A normal of the object's coordinates, in the world (unit).
    dvec3 world_normal(const dvec3& n) const;
};

struct Object {
    Shape shape;
    HeapOptional<Placement> placement;  // none: the identity (on the heap: most objects have none)
    std::uint32_t material = 0;  // index into Scene::materials
    SourceLocation where;        // the [[object]] table, for messages
    RareString name;             // optional, for [animation] to refer to it (most objects have none)
};

// The material of a hit on `o` whose SurfaceHit::part is `part`: a mesh triangle's or a sphere
// set's sphere's own where the file's apply, else the object's.
inline std::uint32_t part_material(const Object& o, int part) {
    if (const auto* m = std::get_if<Mesh>(&o.shape)) return m->material_of(static_cast<std::size_t>(part), o.material);
    if (const auto* s = std::get_if<SphereSet>(&o.shape)) return s->material_of(static_cast<std::size_t>(part), o.material);
    return o.material;
}

// Calls visit(object) for each object and, after a CSG object, for each of its leaves: the
// order the GPU packs them in (the generated surface functions are numbered in it).
template <class Visit>
void for_each_object_and_leaf(const std::vector<Object>& objects, Visit&& visit) {
    for (const Object& o : objects) {
        visit(o);
        if (const auto* csg = std::get_if<Csg>(&o.shape))
            for (const Object& leaf : csg->leaves) visit(leaf);
    }
}

struct Animation;  // scene/animation.hpp
struct Scene;

// Photon mapping shoots photons by power: every light must have one (fall-off with distance).
// A SceneError at the first light that has none.
void check_photon_lights(const Scene& scene);

// POV-Ray's constant fog (docs/scene-format.md, "[fog]"): along every ray a segment of length d
// lets exp(-d / distance) of what lies beyond through and adds the rest in `color`; a ray that
// meets nothing is all fog. Light on its way to a surface is not fogged (POV-Ray's rule).
struct Fog {
    dvec3 color{0.5};
    double distance = 1.0;
    // POV-Ray's ground fog (fog_type 2): the fog's density is 1 up to `offset` along `up`, and
    // 1 / (1 + Y^2) above it, Y the height above `offset` in units of `altitude`.
    struct Ground {
        dvec3 up{0.0, 1.0, 0.0};  // unit
        double offset = 0.0;
        double altitude = 1.0;
    };
    std::optional<Ground> ground;
};

// The fog's depth along a segment: its density integrated over it, exactly (POV-Ray's constant
// and ground fog), from `from` along the unit direction `dir` for `length` (infinite: a ray that
// meets nothing; infinite where the density does not fall off). What lies behind shows through
// exp(-depth / fog.distance).
double fog_depth(const Fog& fog, const dvec3& from, const dvec3& dir, double length);

// POV-Ray's sky_sphere (docs/scene-format.md, "[sky]"): what a ray that meets nothing sees, the
// colour ramp at its direction's height, wrapped as POV-Ray's gradient y is (d.y - floor(d.y):
// from the horizon up, and again from below it); or, with a pattern, the pattern's colour at the
// unit direction (POV-Ray's pigment on the sky sphere), its ramp these colours.
struct Sky {
    std::vector<ColorStop> colors;
    std::optional<Pattern> pattern;  // its colors are `colors`
};
struct Scene {
    std::string path;
    RenderSettings render;
    CameraSpec camera;
    dvec3 ambient{1.0};  // I_scene, scaled per material by Material::ambient
    std::optional<PhotonSettings> photons;  // photon mapping, when the scene or the command line asks for it
    std::optional<Fog> fog;
    std::optional<Sky> sky;
    std::vector<Light> lights;
    std::vector<Material> materials;
    std::vector<Object> objects;
    // Files the scene read besides itself (patch files, textures), for `lancer watch` and `view`.
    std::vector<std::string> dependencies;
    // Set when the file has an [animation] table; scene_at() (scene/animation.hpp) turns the
    // scene into the static one of a moment. Renderers ignore it.
    std::shared_ptr<const Animation> animation;
    // Some number is an expression of clock or frame: each frame of an animation reads the file
    // again at its time (scene_values.hpp).
    bool depends_on_time = false;
};

}  // namespace lancer

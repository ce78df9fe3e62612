#include "fuzz/fuzz_entries.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <unistd.h>
#include <glm/geometric.hpp>

#include "accel/bvh.hpp"
#include "scene/shape_bounds.hpp"
#include "scene/prism.hpp"
#include "cpu/cpu_renderer.hpp"
#include "cpu/shapes/shapes.hpp"
#include "gpu/packing/scene_packing.hpp"
#include "gpu/shaders/spirv_cache.hpp"
#include "image/image.hpp"
#include "scene/animation.hpp"
#include "scene/camera.hpp"
#include "scene/load_scene.hpp"
#include "surface/expr/domain_check.hpp"
#include "surface/expr/evaluate.hpp"
#include "gpu/shaders/glsl_emitter.hpp"
#include "surface/expr/gpu_float.hpp"
#include "surface/expr/parser.hpp"
#include "surface/expr/program.hpp"
#include "surface/float_check.hpp"
#include "surface/patch_file.hpp"
#include "surface/polynomial.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/ply_reader.hpp"
#include "fuzz/plain_toml_check.hpp"
#include "core/magnitude.hpp"

namespace lancer::fuzz {
namespace {

std::string_view as_text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

// The message of a failed check is the concatenation of `what`, put together only when the check
// fails: the checks run for every cell, grid entry and pixel, and building their messages up
// front took a third of the scene fuzzer's time (AddressSanitizer's allocator).
template <class... Parts>
void require(bool ok, const Parts&... what) {
    if (ok) return;
    std::string message;
    (message.append(std::string_view(what)), ...);
    throw InvariantBroken(message);
}

template <class... Parts>
void require_finite(double x, const Parts&... what) {
    require(std::isfinite(x), what..., " is not finite");
}
template <class... Parts>
void require_finite(const dvec3& v, const Parts&... what) {
    for (int i = 0; i < 3; ++i) require_finite(v[i], what...);
}

template <class... Parts>
void check_patch(const surface::BezierPatch& p, const Parts&... what) {
    for (const dvec3& point : p.points) require_finite(point, what..., " control point");
    for (double w : p.weights) require(std::isfinite(w) && w > 0.0, what..., " weight is not finite and positive");
}

}  // namespace

void check_scene_invariants(const Scene& scene, const std::string& when) {
    const RenderSettings& r = scene.render;
    require(r.width >= 1 && r.height >= 1 && r.samples >= 1 && r.max_depth >= 0, when, ": render settings");
    require_finite(r.background, when, ": background");
    require_finite(scene.ambient, when, ": ambient");
    require_finite(scene.camera.eye, when, ": camera eye");
    require_finite(scene.camera.look_at, when, ": camera look_at");
    require_finite(scene.camera.up, when, ": camera up");
    make_camera_basis(scene.camera, r.width, r.height);  // a UserError here escapes as a bug: the loader accepted it
    for (const Light& l : scene.lights) {
        require_finite(l.position, when, ": light position");
        require_finite(l.color, when, ": light color");
        require(l.color.r >= 0.0 && l.color.g >= 0.0 && l.color.b >= 0.0, when, ": light color is negative");
        require(std::isfinite(l.falloff_distance) && l.falloff_distance > 0.0, when, ": light falloff_distance");
        require_finite(l.direction, when, ": spot direction");
        require(std::abs(glm::length(l.direction) - 1.0) < 1e-9, when, ": spot direction is not a unit vector");
        require(0.0 <= l.inner_angle_deg && l.inner_angle_deg <= l.outer_angle_deg && l.outer_angle_deg < 180.0,
                when, ": spot angles");
        require(std::isfinite(l.tightness) && l.tightness >= 0.0, when, ": spot tightness");
        require_finite(l.edge_u, when, ": area light edge_u");
        require_finite(l.edge_v, when, ": area light edge_v");
        require(l.samples >= 1, when, ": area light samples");
    }
    require(!scene.materials.empty(), when, ": no default material");
    for (const Material& m : scene.materials) {
        require_finite(m.color, when, ": material color");
        for (double x : {m.ambient, m.diffuse, m.specular, m.shininess, m.reflection}) require_finite(x, when, ": material");
        require_finite(m.transmission, when, ": material transmission");
        require_finite(m.absorption, when, ": material absorption");
        require(std::isfinite(m.ior) && m.ior > 0.0, when, ": material ior");
        if (m.checker) {
            require_finite(m.checker->color_a, when, ": checker");
            require_finite(m.checker->color_b, when, ": checker");
            require(std::isfinite(m.checker->size) && m.checker->size > 0.0, when, ": checker size");
        }
    }
    std::vector<Aabb> boxes;
    for (const Object& o : scene.objects) {
        require(o.material < scene.materials.size(), when, ": material index");
        std::visit(
            [&](const auto& s) {
                using T = std::decay_t<decltype(s)>;
                if constexpr (std::is_same_v<T, Sphere>) {
                    require_finite(s.center, when, ": sphere");
                    require(std::isfinite(s.radius) && s.radius > 0.0, when, ": sphere radius");
                } else if constexpr (std::is_same_v<T, Plane>) {
                    require_finite(s.point, when, ": plane");
                    require_finite(s.normal, when, ": plane normal");
                } else if constexpr (std::is_same_v<T, Rectangle>) {
                    require_finite(s.corner, when, ": rectangle");
                    require_finite(s.edge_u, when, ": rectangle");
                    require_finite(s.edge_v, when, ": rectangle");
                } else if constexpr (std::is_same_v<T, Disc>) {
                    require_finite(s.center, when, ": disc");
                    require_finite(s.normal, when, ": disc normal");
                    require(std::isfinite(s.radius) && s.radius > 0.0, when, ": disc radius");
                    require(s.hole_radius >= 0.0 && s.hole_radius < s.radius, when, ": disc hole radius");
                } else if constexpr (std::is_same_v<T, Cone>) {
                    require_finite(s.base, when, ": cone base");
                    require_finite(s.cap, when, ": cone cap");
                    require(glm::length(s.cap - s.base) > 0.0, when, ": cone axis");
                    require(std::isfinite(s.base_radius) && s.base_radius >= 0.0, when, ": cone base radius");
                    require(std::isfinite(s.cap_radius) && s.cap_radius >= 0.0, when, ": cone cap radius");
                    require(s.base_radius > 0.0 || s.cap_radius > 0.0, when, ": cone radii");
                    require_finite(s.u_axis, when, ": cone texture axis");
                } else if constexpr (std::is_same_v<T, Csg>) {
                    require(!s.leaves.empty() && s.leaves.size() <= CSG_MAX_LEAVES, when, ": CSG leaves");
                    require_finite(s.lo, when, ": CSG box");
                    require_finite(s.hi, when, ": CSG box");
                    for (const Object& leaf : s.leaves) {
                        const std::uint32_t kind = shape_type(leaf.shape);
                        const auto* cone = std::get_if<Cone>(&leaf.shape);
                        const auto* sor = std::get_if<Sor>(&leaf.shape);
                        const auto* prism = std::get_if<Prism>(&leaf.shape);
                        require((shape_has(kind, SHAPE_SOLID) || shape_has(kind, SHAPE_CLOSED) ||
                                 (shape_has(kind, SHAPE_ORIENTED) && outward_side(leaf.shape) != 0)) &&
                                    !(cone && cone->open) && !(sor && sor->open) && !(prism && prism->open) &&
                                    leaf.material < scene.materials.size(),
                                when, ": CSG leaf");
                    }
                } else if constexpr (std::is_same_v<T, Torus>) {
                    require_finite(s.center, when, ": torus");
                    require_finite(s.axis, when, ": torus axis");
                    require(std::abs(glm::length(s.axis) - 1.0) < 1e-9, when, ": torus axis not unit");
                    require(std::isfinite(s.major_radius) && s.major_radius > 0.0, when, ": torus major radius");
                    require(std::isfinite(s.minor_radius) && s.minor_radius > 0.0, when, ": torus minor radius");
                } else if constexpr (std::is_same_v<T, Blob>) {
                    require(std::isfinite(s.threshold) && s.threshold > 0.0, when, ": blob threshold");
                    require(!s.components.empty(), when, ": blob without components");
                    for (const BlobComponent& k : s.components) {
                        require_finite(k.a, when, ": blob component");
                        require_finite(k.b, when, ": blob component");
                        require(std::isfinite(k.radius) && k.radius > 0.0, when, ": blob component radius");
                        require(std::isfinite(k.strength) && k.strength != 0.0, when, ": blob component strength");
                    }
                    require_finite(s.lo, when, ": blob box");
                    require_finite(s.hi, when, ": blob box");
                } else if constexpr (std::is_same_v<T, Sor>) {
                    require(!s.segments.empty(), when, ": sor without segments");
                    for (const SorSegment& g : s.segments) {
                        require(std::isfinite(g.a) && std::isfinite(g.b) && std::isfinite(g.c) && std::isfinite(g.d), when,
                                ": sor coefficients");
                        require(g.y0 < g.y1 && std::isfinite(g.r_max) && g.r_max >= 0.0, when, ": sor segment");
                    }
                    require(std::isfinite(s.r_max) && s.r_max > 0.0, when, ": sor radius");
                    require(o.placement && o.placement->shape_in_object_space, when, ": a sor is always placed");
                } else if constexpr (std::is_same_v<T, Prism>) {
                    require(!s.segments.empty(), when, ": prism without segments");
                    for (const PrismSegment& g : s.segments) {
                        require(g.degree >= 1 && g.degree <= 3, when, ": prism segment degree");
                        for (int i = 0; i <= g.degree; ++i)
                            require(std::isfinite(g.p[i].x) && std::isfinite(g.p[i].y), when, ": prism control point");
                    }
                    require(prism_open_contour(s.segments) < 0, when, ": a prism contour that does not close");
                    require(std::isfinite(s.y0) && std::isfinite(s.y1) && s.y0 < s.y1, when, ": prism heights");
                    require(s.tree && !s.tree->nodes.empty(), when, ": prism without its tree");
                    require(o.placement && o.placement->shape_in_object_space, when, ": a prism is always placed");
                } else if constexpr (std::is_same_v<T, Lathe>) {
                    require(!s.segments.empty() && s.degree >= 1 && s.degree <= 3, when, ": lathe without segments");
                    for (const LatheSegment& g : s.segments) {
                        for (int i = 0; i <= s.degree; ++i) {
                            require_finite(g.r[i], when, ": lathe radius");
                            require_finite(g.y[i], when, ": lathe height");
                        }
                        require(g.r[0] >= 0.0 && g.r[s.degree] >= 0.0 && g.r_max >= 0.0 && g.y_lo <= g.y_hi, when,
                                ": lathe segment");
                        require(g.side == 1 || g.side == -1, when, ": lathe side");
                    }
                    require(std::isfinite(s.r_max) && s.r_max > 0.0, when, ": lathe radius");
                    require(o.placement && o.placement->shape_in_object_space, when, ": a lathe is always placed");
                } else if constexpr (std::is_same_v<T, Superellipsoid>) {
                    require(s.e >= 0.001 && s.e <= 2.0 && s.n >= 0.001 && s.n <= 2.0, when, ": superellipsoid exponents");
                    require(o.placement && o.placement->shape_in_object_space, when, ": a superellipsoid is always placed");
                } else if constexpr (std::is_same_v<T, Mesh>) {
                    require(s.geometry && !s.geometry->mesh().triangles.empty(), when, ": mesh without triangles");
                    const TriangleMesh& m = s.geometry->mesh();
                    for (const auto& t : m.triangles)
                        for (std::uint32_t v : t) require(v < m.positions.size(), when, ": mesh index");
                    for (const dvec3& p : m.positions) require_finite(p, when, ": mesh vertex");
                    require(m.normals.size() == m.positions.size(), when, ": mesh normals");
                    require(o.placement && o.placement->shape_in_object_space, when, ": a mesh is always placed");
                } else if constexpr (std::is_same_v<T, SphereSet>) {
                    require(s.cloud && !s.cloud->spheres().empty(), when, ": sphere set without spheres");
                    for (const glm::vec4& e : s.cloud->spheres())
                        require(std::isfinite(e.x) && std::isfinite(e.y) && std::isfinite(e.z) && e.w > 0.0f && std::isfinite(e.w),
                                when, ": set sphere");
                    require(s.cloud->colors().empty() || s.cloud->colors().size() == s.cloud->spheres().size(), when,
                            ": set colours");
                    for (std::uint32_t c : s.cloud->colors()) require(c < s.cloud->palette().size(), when, ": set colour index");
                    for (std::uint32_t m : s.part_materials) require(m < scene.materials.size(), when, ": set material");
                    require(o.placement && o.placement->shape_in_object_space, when, ": a sphere set is always placed");
                } else if constexpr (std::is_same_v<T, Box>) {
                    require_finite(s.min, when, ": box");
                    require_finite(s.max, when, ": box");
                } else if constexpr (std::is_same_v<T, BezierSurface>) {
                    require(!s.patches.empty(), when, ": bezier object without patches");
                    for (const auto& p : s.patches) check_patch(p, when, ": bezier");
                } else if constexpr (std::is_same_v<T, ParametricObject>) {
                    require_finite(s.bounds_lo, when, ": parametric surface's bounds");
                    require_finite(s.bounds_hi, when, ": parametric surface's bounds");
                    require(glm::all(glm::lessThanEqual(s.bounds_lo, s.bounds_hi)), when, ": parametric bounds are empty");
                } else if constexpr (std::is_same_v<T, ImplicitObject>) {
                    const surface::ImplicitSurface& f = *s.surface;
                    require_finite(f.box_lo, when, ": implicit box");
                    require_finite(f.box_hi, when, ": implicit box");
                    require(glm::all(glm::lessThan(f.box_lo, f.box_hi)), when, ": implicit box is empty");
                    require(f.program.outputs.size() == 1, when, ": implicit function not compiled");
                    require(!f.polynomial || (f.polynomial->degree() >= 1 &&
                                              f.polynomial->degree() <= surface::kMaxPolynomialDegree),
                            when, ": implicit polynomial degree");
                    for (int c = 0; c < 4; ++c) {
                        for (int r = 0; r < 4; ++r) {
                            require(std::isfinite(f.to_world[c][r]), when, ": implicit transform");
                            require(std::isfinite(f.to_local[c][r]), when, ": implicit inverse transform");
                        }
                    }
                } else {
                    static_assert(sizeof(T) == 0, "a shape of the registry without its invariants here");
                }
            },
            o.shape);
        if (o.placement) {  // both maps finite: the renderers use both
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    require(std::isfinite(o.placement->to_world[c][r]) && std::isfinite(o.placement->to_object[c][r]), when,
                            ": placement");
        }
        if (auto box = object_bounds(o)) {
            require_finite(box->lo, when, ": object box");
            require_finite(box->hi, when, ": object box");
            boxes.push_back(*box);
        }
    }
    Bvh bvh = build_bvh(boxes);
    require(bvh.order.size() == boxes.size(), when, ": the BVH lost primitives");
}

namespace {

template <class V, class... Parts>
void require_finite_floats(const V& v, const Parts&... what) {
    for (int i = 0; i < 4; ++i) require(std::isfinite(v[i]), what..., " is not finite in float");
}

// What the renderers make of an accepted scene, rendered tiny: the GPU's packed buffers (every
// float finite: the magnitude limit at work) and the CPU reference's pixels (finite).
void check_renderers_input(const Scene& accepted, const std::string& when) {
    Scene scene = accepted;
    scene.render.width = 3;
    scene.render.height = 2;
    scene.render.samples = 1;
    scene.render.max_depth = std::min(scene.render.max_depth, 3);
    gpu::PackedScene packed = gpu::pack_scene(scene);
    // Packed again as lancer render's still is, its objects freed as they are packed (from the
    // back where each is one cheap shape): the same primitives, byte for byte.
    Scene given = scene;
    gpu::PackOptions releasing;
    releasing.release_objects = &given.objects;
    const gpu::PackedScene released = gpu::pack_scene(given, releasing);
    require(given.objects.empty(), when, ": the released objects were kept");
    require(released.primitives.size() == packed.primitives.size() &&
                (packed.primitives.empty() ||
                 std::memcmp(released.primitives.data(), packed.primitives.data(), packed.primitives.size() * sizeof(gpu::Primitive)) == 0),
            when, ": packing while freeing the objects made other primitives");
    gpu::FrameParams frame = gpu::pack_frame(scene, packed);
    for (const auto& v : {frame.eye, frame.forward, frame.right, frame.up, frame.background, frame.ambient})
        require_finite_floats(v, when, ": frame");
    for (const auto& p : packed.primitives)
        for (const auto& v : {p.p0, p.p1, p.p2}) require_finite_floats(v, when, ": primitive");
    for (const auto& n : packed.nodes) {
        require_finite_floats(n.lo, when, ": BVH node");
        require_finite_floats(n.hi, when, ": BVH node");
    }
    for (const auto& leaf : packed.patches)
        for (const auto& v : leaf.points) require_finite_floats(v, when, ": patch leaf");
    for (const auto& c : packed.cells)
        for (const auto& v : {c.domain, c.su_lo, c.su_hi, c.sv_lo, c.sv_hi, c.centre, c.suu, c.suv, c.svv}) require_finite_floats(v, when, ": parametric cell");
    for (const auto& s : packed.surfaces)
        for (const auto& v : {s.row0, s.row1, s.row2, s.inverse0, s.inverse1, s.inverse2, s.domain})
            require_finite_floats(v, when, ": surface info");
    for (const auto& b : packed.lathe_bands)
        for (const auto& v : {b.radius, b.height, b.band}) require_finite_floats(v, when, ": lathe segment");
    for (const auto& m : packed.materials)
        for (const auto& v : {m.color, m.color2, m.phong}) require_finite_floats(v, when, ": material");
    for (const auto& l : packed.lights) {
        require_finite_floats(l.position, when, ": light");
        require_finite_floats(l.color, when, ": light");
    }
    // Direction grids: finite frames and windows, cells within the arrays, entries that name
    // primitives of the BVH, nearest first.
    const std::size_t in_bvh = packed.primitives.size() - packed.unbounded_count;
    for (const gpu::DirectionGrid& g : packed.grids) {
        if (!g.valid) continue;
        for (const auto& v : {g.origin, g.axis, g.across_u, g.across_v, g.window}) require_finite_floats(v, when, ": direction grid");
        const std::size_t cells = std::size_t(g.columns) * g.rows;
        require(g.columns > 0 && g.rows > 0 && g.first_cell + cells < packed.grid_cells.size(), when, ": direction grid cells");
        for (std::size_t c = g.first_cell; c < g.first_cell + cells; ++c) {
            const uint first = packed.grid_cells[c], end = packed.grid_cells[c + 1];
            require(first <= end && 2 * std::size_t(end) <= packed.grid_entries.size(), when, ": direction grid cell");
            float last = 0.0f;
            for (uint e = first; e < end; ++e) {
                float near;
                std::memcpy(&near, &packed.grid_entries[2 * e + 1], sizeof near);
                require(packed.grid_entries[2 * e] < in_bvh, when, ": direction grid entry names no primitive of the BVH");
                require(std::isfinite(near) && near >= last, when, ": direction grid entries not nearest first");
                last = near;
            }
        }
    }
    if (packed.features.grids_only)
        require(packed.grids.at(gpu::DIRECTION_GRID_EYE).valid != 0, when, ": every ray takes a grid, but the eye has none");
    FloatImage image = CpuRenderer(1).render(scene, {});
    for (const auto& pixel : image.pixels) require_finite_floats(pixel, when, ": a pixel of the CPU reference");
}

}  // namespace

void scene_entry(const std::uint8_t* data, std::size_t size) {
    // Patch files named in the scene are found beside the shipped scenes (file = "teapot.bpt").
    static const std::string path = std::string(LANCER_SOURCE_DIR) + "/scenes/fuzz-input.toml";
    check_plain_toml(as_text(data, size), path);
    Scene scene;
    try {
        scene = parse_scene(as_text(data, size), path);
    } catch (const UserError&) {
        return;  // rejected with a message: the expected outcome for most inputs
    }
    check_scene_invariants(scene, "the scene");
    if (!scene.animation) {
        check_renderers_input(scene, "the scene");
        return;
    }
    const Animation& a = *scene.animation;
    for (int frame : {0, a.frames / 2, a.frames - 1}) {
        Scene still = scene_at(scene, frame_time(a, frame));
        check_scene_invariants(still, fmt::format("frame {}", frame));
        check_renderers_input(still, fmt::format("frame {}", frame));
    }
}

namespace {

const surface::Constants kFuzzConstants{{"a", 2.0}, {"R", 1.0}, {"r", 0.35}, {"k", -3.0}};

void require_column(int column, std::size_t size, std::string_view what) {
    require(column >= 0 && column <= static_cast<int>(size), what, "'s column is outside the text");
}

// The text as an implicit surface's f(x, y, z) over the box [-1, 1]^3, as the scene loader
// takes it: parsed, expanded when it is a polynomial (within the degree limit), checked for being
// defined, emitted as GLSL, and intersected by the CPU reference along two rays, whose roots must
// be finite, in order, inside the box, with finite unit normals.
void implicit_expression(std::string_view text) {
    surface::ImplicitSurface s;
    try {
        s.f = surface::parse_expression(text, kFuzzConstants, surface::kImplicitVariables);
    } catch (const UserError&) {
        return;
    }
    for (const surface::Node& n : s.f.nodes)
        require(n.op != surface::Op::Variable || (n.value >= 0.0 && n.value <= 2.0), "a variable beyond z");
    try {
        s.polynomial = surface::expand_polynomial(s.f);
    } catch (const surface::ExprError& error) {
        require_column(error.column, text.size(), "a degree error");
        return;
    }
    if (s.polynomial) require(s.polynomial->degree() <= surface::kMaxPolynomialDegree, "a polynomial above the limit");
    const surface::Interval box[] = {{-1.0, 1.0}, {-1.0, 1.0}, {-1.0, 1.0}};
    try {
        surface::check_expression_domain(s.f, box);
    } catch (const surface::ExprError& error) {
        require_column(error.column, text.size(), "an implicit domain error");
        return;
    }
    if (auto origin = surface::where_non_finite_starts(s.f, box)) {
        require_column(origin->column, text.size(), "a non-finite implicit function");
        return;
    }
    try {
        surface::check_float_constants(s.f);
    } catch (const surface::ExprError& error) {
        require_column(error.column, text.size(), "an implicit float constant error");
        return;
    }
    const surface::Expr* f[] = {&s.f};
    s.program = surface::compile_program(f);
    try {
        surface::check_float_evaluation(s, 4);  // a coarse grid: the fuzzer's time goes to many inputs
    } catch (const surface::FloatEvaluationError& error) {
        require_column(error.column, text.size(), "an implicit float evaluation error");
        return;
    }
    s.place(glm::dmat4(1.0));
    gpu::emit_glsl_implicit(s.f, "fuzz_implicit");
    for (const cpu::Ray& ray : {cpu::Ray{{-3.0, 0.1, 0.2}, glm::normalize(dvec3(1.0, 0.05, -0.1))},
                                cpu::Ray{{0.3, 2.5, -0.4}, dvec3(0.0, -1.0, 0.0)}}) {
        double last = 0.0;
        for (const cpu::ImplicitRoot& root : cpu::implicit_roots(s, ray, 0.0, 1e9)) {
            require(std::isfinite(root.t) && root.t > last, "implicit roots are not finite and in order");
            last = root.t;
            dvec3 p = ray.origin + root.t * ray.dir;
            require(glm::all(glm::lessThanEqual(glm::abs(p), dvec3(1.0 + 1e-9))), "an implicit root outside its box");
            dvec3 n = surface::implicit_normal(s, p);
            require(std::abs(glm::length(n) - 1.0) < 1e-9, "an implicit normal is not a finite unit vector");
        }
    }
}

// The GPU evaluates in float. An expression the loader's float check accepts
// (surface/float_check.hpp, which samples a 65 x 65 grid) must evaluate to finite floats, value
// and derivatives, wherever double gives finite values within float's range (here: up to 1e30),
// at points between the grid's too. (A coarse grid first, for speed; the loader's only where the
// points between find something: v^v^-32 slipped through the coarse one, and the loader's
// refuses it.)
void check_gpu_float(const surface::Expr& e, int size) {
    try {
        surface::check_float_constants(e);
    } catch (const surface::ExprError& error) {
        require(error.column >= 0 && error.column <= size, "a float constant error's column is outside the text");
        return;
    }
    surface::ParametricSurface s;
    s.x = e;
    s.y = e;
    s.z = e;
    const surface::Expr* xyz[] = {&s.x, &s.y, &s.z};
    const surface::Program program = surface::compile_program(xyz);
    try {
        surface::check_float_evaluation(program, s, 4);  // a coarse grid: the points below lie between its points
    } catch (const surface::FloatEvaluationError& error) {
        require(error.column >= 0 && error.column <= size, "a float evaluation error's column is outside the text");
        require(error.expression >= 0 && error.expression < 3, "a float evaluation error names no expression");
        return;
    }
    auto representable = [](double x) { return std::isfinite(x) && std::abs(x) <= 1e30; };
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const double u = static_cast<float>((i + 0.37) / 8), v = static_cast<float>((j + 0.61) / 8);
            surface::Dual<double> d[3];
            surface::evaluate_program(program, surface::Dual<double>::variable_u(u), surface::Dual<double>::variable_v(v), d);
            surface::Dual<surface::GpuFloat> f[3];
            surface::evaluate_program(program, surface::Dual<surface::GpuFloat>::variable_u(surface::GpuFloat(u)),
                                      surface::Dual<surface::GpuFloat>::variable_v(surface::GpuFloat(v)), f);
            if (!representable(d[0].v) || !representable(d[0].du) || !representable(d[0].dv)) continue;
            if (std::isfinite(f[0].v.x) && std::isfinite(f[0].du.x) && std::isfinite(f[0].dv.x)) continue;
            // The coarse grid missed it; the loader's grid (65 x 65) must not.
            try {
                surface::check_float_evaluation(program, s);
            } catch (const surface::FloatEvaluationError&) {
                return;
            }
            require(false, fmt::format("accepted by the loader's float check, but not finite in float at ({}, {}) where "
                                       "double gives {}, {}, {}",
                                       u, v, d[0].v, d[0].du, d[0].dv));
        }
    }
}

}  // namespace

void expression_entry(const std::uint8_t* data, std::size_t size) {
    implicit_expression(as_text(data, size));
    const surface::Constants& constants = kFuzzConstants;
    surface::Expr e;
    try {
        e = surface::parse_expression(as_text(data, size), constants);
    } catch (const UserError&) {
        return;
    }
    require(!e.nodes.empty(), "an accepted expression has no nodes");
    for (std::size_t i = 0; i < e.nodes.size(); ++i) {
        const surface::Node& n = e.nodes[i];
        require(n.a < static_cast<int>(i) && n.b < static_cast<int>(i), "nodes are not in post-order");
        require(n.column >= 0 && n.column <= static_cast<int>(size), "a node's column is outside the text");
    }
    // Any value is allowed here (NaN outside the domain); what must not happen is a crash or UB.
    surface::evaluate(e, 0.25, 0.75);
    surface::evaluate(e, surface::Interval(-1.0, 2.0), surface::Interval(0.0, 1.0));
    surface::evaluate(e, surface::Dual<double>::variable_u(0.5), surface::Dual<double>::variable_v(-0.5));
    surface::evaluate(e, surface::Dual<surface::Interval>::variable_u(surface::Interval(0.0, 1.0)),
                      surface::Dual<surface::Interval>::variable_v(surface::Interval(1.0, 3.0)));
    try {
        surface::check_expression_domain(e, {0.0, 1.0}, {0.0, 1.0});
    } catch (const surface::ExprError& error) {
        require(error.column >= 0 && error.column <= static_cast<int>(size), "a domain error's column is outside the text");
        return;
    }
    gpu::emit_glsl_surface(e, e, e, "fuzz_surface");
    check_gpu_float(e, static_cast<int>(size));
}

void patch_entry(const std::uint8_t* data, std::size_t size) {
    std::vector<surface::BezierPatch> patches;
    try {
        patches = surface::parse_patch_text(as_text(data, size), "fuzz.bpt");
    } catch (const UserError&) {
        return;
    }
    require(!patches.empty(), "an accepted patch file has no patches");
    for (const auto& p : patches) {
        check_patch(p, "patch");
        surface::bounds(p);
        auto [left, right] = surface::split_u(p, 0.5);
        check_patch(left, "split patch");
        require_finite(surface::evaluate(p, 0.5, 0.5), "patch point");
        require_finite(surface::unit_normal(p, 0.0, 0.0), "patch normal");
    }
}

namespace {

// Where cache_file_entry writes its entry: a directory of this process's own, removed at exit
// (the path is never freed: the handler may run after static objects are destroyed).
const std::string& cache_entry_path() {
    static const std::string* path = [] {
        namespace fs = std::filesystem;
        const fs::path dir = fs::temp_directory_path() / fmt::format("lancer-fuzz-cache-{}", ::getpid());
        fs::create_directories(dir);
        auto* p = new std::string((dir / "entry.spv").string());
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(std::filesystem::path(*path).parent_path(), ec);
        });
        return p;
    }();
    return *path;
}

// The shader files a fuzzed compile's manifest is checked against.
std::optional<std::string> cache_fuzz_tree(const std::string& name) {
    static const std::map<std::string, std::string> files{{"main.comp", "#version 450\n#include \"a.glsl\"\nvoid main() {}\n"},
                                                          {"a.glsl", "float a() { return 1.0; }\n"}};
    if (auto f = files.find(name); f != files.end()) return f->second;
    return std::nullopt;
}

std::vector<std::uint32_t> words_of(std::string_view bytes) {
    std::vector<std::uint32_t> words(bytes.size() / 4);
    if (!words.empty()) std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}

}  // namespace

void cache_file_entry(const std::uint8_t* data, std::size_t size) {
    namespace entry = gpu::cache_entry;
    if (size == 0) return;
    const bool compiled = data[0] & 1, sealed = data[0] & 2;
    const std::string_view rest = as_text(data + 1, size - 1);
    // The key a lookup asks for: that of a fixed set of inputs.
    static const Sha256Digest key = sha256("lancer fuzz: the key looked up");
    std::string bytes;
    std::vector<std::uint32_t> sealed_words;
    if (!sealed) {
        bytes = std::string(rest);
    } else if (!compiled) {
        sealed_words = words_of(rest);
        bytes = entry::encode_specialization(key, sealed_words);
    } else {
        const std::size_t manifest_bytes = rest.size() < 2 ? 0 : std::min<std::size_t>(
            rest.size() - 2, static_cast<unsigned char>(rest[0]) | static_cast<std::size_t>(static_cast<unsigned char>(rest[1])) << 8);
        const std::string manifest(rest.substr(std::min<std::size_t>(2, rest.size()), manifest_bytes));
        sealed_words = words_of(rest.substr(std::min<std::size_t>(2, rest.size()) + manifest_bytes));
        bytes = entry::encode_compiled(key, manifest, sealed_words);
    }
    {
        std::ofstream out(cache_entry_path(), std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        require(bool(out.flush()), "cannot write the fuzz entry");
    }
    const std::optional<std::vector<std::uint32_t>> hit =
        compiled ? entry::read_compiled(cache_entry_path(), key, cache_fuzz_tree) : entry::read_specialization(cache_entry_path(), key);
    if (hit) {
        require(!hit->empty() && hit->size() <= entry::kMaxEntryWords, "a hit of no words or too many");
        const std::size_t word_bytes = hit->size() * sizeof(std::uint32_t);
        require(word_bytes <= bytes.size() && std::memcmp(hit->data(), bytes.data() + bytes.size() - word_bytes, word_bytes) == 0,
                "a hit is not the words at the entry's end");
        if (!compiled) require(entry::encode_specialization(key, *hit) == bytes, "a hit that is not a well-formed entry");
        if (sealed) require(*hit == sealed_words, "a sealed entry's hit is not its words");
    }
    if (sealed && !compiled) require(hit.has_value() == !sealed_words.empty(), "a sealed specialisation with words was a miss");
}

void exr_part_entry(const std::uint8_t* data, std::size_t size) {
    ExrInfo info;
    FloatImage image;
    try {
        image = read_exr_bytes("fuzz.exr", std::string(reinterpret_cast<const char*>(data), size), &info);
    } catch (const UserError&) {
        return;
    }
    const long long pixels = static_cast<long long>(image.width) * image.height;
    require(image.width >= 1 && image.height >= 1 && image.width <= kMaxReadSide && image.height <= kMaxReadSide &&
                pixels <= kMaxReadPixels,
            "an accepted part is beyond the size limits");
    require(static_cast<long long>(image.pixels.size()) == pixels, "an accepted part's pixels do not match its size");
    // Three channels of at least 2 bytes each, compressed at best 1032 : 1 (deflate).
    require(double(pixels) * 6.0 <= double(size) * 1032.0, "an accepted part has more pixels than its bytes can hold");
    require(std::isfinite(info.tone.exposure) && std::abs(info.tone.exposure) <= kMaxExposureStops,
            "an accepted part's exposure is not finite or out of range");
}

void check_mesh_invariants(const TriangleMesh& mesh) {
    const std::size_t n = mesh.positions.size();
    require(!mesh.triangles.empty(), "an accepted mesh has no triangles");
    require(mesh.normals.empty() || mesh.normals.size() == n, "normals: neither none nor one per position");
    require(mesh.uvs.empty() || mesh.uvs.size() == n, "uvs: neither none nor one per position");
    for (const dvec3& p : mesh.positions)
        for (int i = 0; i < 3; ++i) require(std::isfinite(p[i]) && std::abs(p[i]) <= kMaxMagnitude, "a position is not finite and within 1e12");
    for (const dvec3& v : mesh.normals) {
        require_finite(v, "a normal");
        require(std::abs(glm::length(v) - 1.0) < 1e-9, "a normal is not a unit vector");
    }
    for (const glm::dvec2& uv : mesh.uvs)
        for (int i = 0; i < 2; ++i) require(std::isfinite(uv[i]) && std::abs(uv[i]) <= kMaxMagnitude, "a texture coordinate is not finite and within 1e12");
    for (const auto& t : mesh.triangles)
        for (std::uint32_t i : t) require(i < n, "a triangle's index is out of range");
    require(mesh.triangle_materials.empty() || mesh.triangle_materials.size() == mesh.triangles.size(),
            "triangle_materials: neither none nor one per triangle");
    for (std::uint32_t m : mesh.triangle_materials) require(m < mesh.materials.size(), "a triangle's material index is out of range");
    for (const MeshMaterial& m : mesh.materials) {
        require_finite(m.diffuse, "a material's Kd");
        require_finite(m.specular, "a material's Ks");
        require(std::isfinite(m.shininess) && m.opacity >= 0.0 && m.opacity <= 1.0, "a material's Ns or d");
    }
}

void obj_entry(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = as_text(data, size);
    constexpr std::string_view kMtlMark = "\n#MTL\n";
    const std::size_t mark = text.find(kMtlMark);
    const std::string mtl(mark == std::string_view::npos ? std::string_view() : text.substr(mark + kMtlMark.size()));
    mesh::ObjCompanions companions;
    companions.folder = "fuzz";
    companions.read_mtl = [&](const std::string& path) -> std::string {
        if (mark == std::string_view::npos) throw UserError(fmt::format("{}: No such file or directory", path));
        return mtl;
    };
    companions.texture_exists = [](const std::string& path) { return path.ends_with(".png"); };
    TriangleMesh mesh;
    try {
        mesh = mesh::read_obj(text.substr(0, mark), "fuzz.obj", companions);
    } catch (const UserError&) {
        return;
    }
    check_mesh_invariants(mesh);
}

namespace {

// The same bytes as a sphere set's point set too (with and without the object's radius): every
// sphere finite with a radius above 0, every colour in the palette.
void check_point_set(std::string_view text, std::optional<double> radius) {
    std::shared_ptr<const SphereCloud> cloud;
    try {
        cloud = mesh::read_sphere_ply(text, "fuzz.ply", radius);
    } catch (const UserError&) {
        return;
    }
    require(!cloud->spheres().empty(), "ply points", ": no spheres");
    for (const glm::vec4& e : cloud->spheres())
        require(std::isfinite(e.x) && std::isfinite(e.y) && std::isfinite(e.z) && std::isfinite(e.w) && e.w > 0.0f, "ply points",
                ": sphere");
    require(cloud->palette().size() <= mesh::kMaxSphereColors, "ply points", ": palette");
    require(cloud->colors().empty() || cloud->colors().size() == cloud->spheres().size(), "ply points", ": colours");
    for (std::uint32_t c : cloud->colors()) require(c < cloud->palette().size(), "ply points", ": colour index");
}

}  // namespace

void ply_entry(const std::uint8_t* data, std::size_t size) {
    check_point_set(as_text(data, size), std::nullopt);
    check_point_set(as_text(data, size), 0.5);
    TriangleMesh mesh;
    try {
        mesh = mesh::read_ply(as_text(data, size), "fuzz.ply");
    } catch (const UserError&) {
        return;
    }
    check_mesh_invariants(mesh);
}

}  // namespace lancer::fuzz

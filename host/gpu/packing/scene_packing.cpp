#include "gpu/packing/scene_packing.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>

#include "accel/bvh.hpp"
#include "accel/shape_bounds.hpp"
#include "gpu/packing/direction_grids.hpp"
#include "gpu/packing/float_anchor.hpp"
#include "core/finite.hpp"
#include "core/perlin_permutation.hpp"
#include "optics/energy.hpp"
#include "optics/ggx.hpp"
#include "scene/camera.hpp"
#include "scene/limits.hpp"
#include "surface/parametric_cells.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace lancer::gpu {
namespace {

// With this few bounded primitives, testing them all beats traversing a tree (measured on
// lavapipe: the BVH loop's stack and divergence cost more than a handful of sphere tests).
constexpr std::size_t kMinPrimitivesForBvh = 16;
// At most this many spheres, rectangles and boxes stay outside a BVH of expensive shapes.
constexpr std::size_t kMaxAnalyticOutsideBvh = 8;

vec4 v4(const dvec3& v, double w = 0.0) { return vec4(float(v.x), float(v.y), float(v.z), float(w)); }

// A box for the shader's slab test, rounded outward to float and padded by a few float ulps of
// its coordinates: the slab test has rounding errors of its own, and a ray aimed exactly at a
// box's edge (a patch corner, which is a control point and so on the box) must not slip past it.
void pack_box(const Aabb& box, vec4& lo, vec4& hi) {
    double pad = 1e-6 * std::max({1.0, glm::length(box.lo), glm::length(box.hi)});
    lo = vec4(round_down(box.lo.x - pad), round_down(box.lo.y - pad), round_down(box.lo.z - pad), 0.0f);
    hi = vec4(round_up(box.hi.x + pad), round_up(box.hi.y + pad), round_up(box.hi.z + pad), 0.0f);
}

// Turns each object into primitives (one, or many for patch sets), each with its box if bounded.
struct PrimitivePacker {
    PackedScene& out;
    std::vector<std::pair<Primitive, std::optional<Aabb>>>& prims;
    uint material = 0;
    uint object = 0;

    void add(Primitive p, std::optional<Aabb> box) { prims.emplace_back(p, box); }

    void operator()(const Sphere& s) {
        add({SHAPE_SPHERE, material, 0, object, v4(s.center, s.radius), v4(s.orientation[0]), v4(s.orientation[1])},
            shape_bounds(s));
    }
    void operator()(const Plane& p) {
        add({SHAPE_PLANE, material, 0, object, v4(p.point), v4(p.normal), v4(p.u_axis)}, std::nullopt);
    }
    void operator()(const Rectangle& r) {
        add({SHAPE_RECTANGLE, material, 0, object, v4(r.corner), v4(r.edge_u), v4(r.edge_v)}, shape_bounds(r));
    }
    void operator()(const Box& b) { add({SHAPE_BOX, material, 0, object, v4(b.min), v4(b.max), {}}, shape_bounds(b)); }

    // Each cell of the surface's domain is a primitive with the cell's proved box; the surface
    // itself (its affine map; its equations are compiled into the shader) is one SurfaceInfo.
    void operator()(const ParametricObject& p) {
        auto index = static_cast<uint>(out.surfaces.size());
        const glm::dmat4& m = p.surface.to_world;  // column-major: m[column][row]
        SurfaceInfo info{};
        info.row0 = vec4(float(m[0][0]), float(m[1][0]), float(m[2][0]), float(m[3][0]));
        info.row1 = vec4(float(m[0][1]), float(m[1][1]), float(m[2][1]), float(m[3][1]));
        info.row2 = vec4(float(m[0][2]), float(m[1][2]), float(m[2][2]), float(m[3][2]));
        const glm::dmat4 inv = glm::inverse(m);
        info.inverse0 = vec4(float(inv[0][0]), float(inv[1][0]), float(inv[2][0]), float(inv[3][0]));
        info.inverse1 = vec4(float(inv[0][1]), float(inv[1][1]), float(inv[2][1]), float(inv[3][1]));
        info.inverse2 = vec4(float(inv[0][2]), float(inv[1][2]), float(inv[2][2]), float(inv[3][2]));
        info.domain = vec4(float(p.surface.u0), float(p.surface.u1), float(p.surface.v0), float(p.surface.v1));
        out.surfaces.push_back(info);
        for (const auto& cell : *surface::surface_cells(p.surface)) {
            // Bounds rounded outward to float; an unbounded one becomes float's largest value,
            // which the search treats as no bound (the packed arrays hold only finite floats).
            auto bound = [](double x, bool upper) {
                constexpr double big = std::numeric_limits<float>::max();
                if (std::isnan(x)) return upper ? float(big) : -float(big);
                if (!(x > -big)) return -float(big);
                if (!(x < big)) return float(big);
                float f = float(x);
                if (upper && double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
                if (!upper && double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
                return f;
            };
            auto lower = [&](const surface::IntervalVec3& b, float w) {
                return vec4(bound(b.x.lo, false), bound(b.y.lo, false), bound(b.z.lo, false), w);
            };
            auto upper = [&](const surface::IntervalVec3& b, float w) {
                return vec4(bound(b.x.hi, true), bound(b.y.hi, true), bound(b.z.hi, true), w);
            };
            auto magnitude = [&](const surface::IntervalVec3& b) {
                auto mag = [&](const surface::Interval& i) {
                    const double m = std::max(-i.lo, i.hi);
                    return bound(m >= 0.0 && !i.is_empty() ? m : surface::kInf, true);
                };
                return vec4(mag(b.x), mag(b.y), mag(b.z), 0.0f);
            };
            ParametricCell c{vec4(float(cell.u0), float(cell.u1), float(cell.v0), float(cell.v1)),
                             lower(cell.Su, float(index)), upper(cell.Su, bound(cell.local_float_pad, true)),
                             lower(cell.Sv, 0.0f), upper(cell.Sv, 0.0f), vec4(0.0f),
                             magnitude(cell.second.Suu), magnitude(cell.second.Suv), magnitude(cell.second.Svv)};
            if (all_finite(cell.centre_point) && glm::all(glm::lessThan(glm::abs(cell.centre_point), dvec3(1e30))))
                c.centre = v4(cell.centre_point, 1.0);
            auto cell_index = static_cast<uint>(out.cells.size());
            out.cells.push_back(c);
            Primitive prim{SHAPE_PARAMETRIC, material, cell_index, object, {}, {}, {}};
            pack_box(Aabb{cell.lo, cell.hi}, prim.p0, prim.p1);
            add(prim, Aabb{cell.lo, cell.hi});
        }
    }

    // One primitive with the box in the surface's own coordinates; its ImplicitInfo carries the
    // map from world space into them (f itself is compiled into the shader).
    void operator()(const ImplicitObject& o) {
        const surface::ImplicitSurface& s = o.surface;
        auto index = static_cast<uint>(out.implicits.size());
        const glm::dmat4& m = s.to_local;  // column-major: m[column][row]
        ImplicitInfo info{};
        info.row0 = vec4(float(m[0][0]), float(m[1][0]), float(m[2][0]), float(m[3][0]));
        info.row1 = vec4(float(m[0][1]), float(m[1][1]), float(m[2][1]), float(m[3][1]));
        info.row2 = vec4(float(m[0][2]), float(m[1][2]), float(m[2][2]), float(m[3][2]));
        out.implicits.push_back(info);
        Aabb world;
        surface::implicit_world_bounds(s, world.lo, world.hi);
        add({SHAPE_IMPLICIT, material, index, object, v4(s.box_lo), v4(s.box_hi), {}}, world);
    }

    // Each patch becomes 2^n x 2^n leaves (exact sub-patches, de Casteljau in double): smaller
    // boxes cull more rays before Bezier clipping starts, and clipping converges sooner.
    void operator()(const BezierSurface& s) {
        const int n = 1 << s.subdivision;
        for (std::size_t i = 0; i < s.patches.size(); ++i) {
            for (int a = 0; a < n; ++a) {
                for (int b = 0; b < n; ++b) {
                    double u0 = double(a) / n, u1 = double(a + 1) / n, v0 = double(b) / n, v1 = double(b + 1) / n;
                    surface::BezierPatch leaf = surface::sub_patch(s.patches[i], u0, u1, v0, v1);
                    surface::PatchBounds pb = surface::bounds(leaf);
                    dvec3 origin = 0.5 * (pb.min + pb.max);
                    // A rational patch is the same for weights scaled by any positive factor, but
                    // float is not: weights of 1e-50 would all be 0. Scaled (by a power of two,
                    // exactly) so that the largest is in [1, 2): weights whose largest is 1 stay.
                    // Equal weights become 1: a polynomial patch, which the GPU clips without
                    // the homogeneous coordinate (SCENE_HAS_RATIONAL_PATCHES).
                    const auto [lightest, heaviest] = std::minmax_element(leaf.weights.begin(), leaf.weights.end());
                    int exponent = 0;
                    std::frexp(*heaviest, &exponent);
                    PatchLeaf g{};
                    for (int k = 0; k < 16; ++k) {
                        double w = *lightest == *heaviest ? 1.0 : std::ldexp(leaf.weights[k], 1 - exponent);
                        g.points[k] = v4(leaf.points[k] - origin, w);
                    }
                    g.origin = v4(origin, double(i));
                    g.domain = vec4(float(u0), float(u1), float(v0), float(v1));
                    auto index = static_cast<uint>(out.patches.size());
                    out.patches.push_back(g);
                    add({SHAPE_BEZIER, material, index, object, {}, {}, {}}, Aabb{pb.min, pb.max});
                }
            }
        }
    }
};

static_assert(PATTERN_MAX_COLORS == limits::kMaxPatternColors);

// Textures and patterns of the materials: images packed once each, a TextureInfo or
// PatternInfo per use.
struct MapPacker {
    PackedScene& out;
    std::map<const TextureImage*, uint> image_offsets;
    std::map<double, std::pair<uint, double>> tables;  // alpha -> (energy table, E_avg)
    dvec3 anchor;                                       // of the GPU's coordinates

    uint texture(const ImageTexture& t) {
        auto [at, added] = image_offsets.emplace(t.image.get(), static_cast<uint>(out.texels.size()));
        if (added) {
            std::size_t first = out.texels.size();
            out.texels.resize(first + t.image->rgba.size() / 4);
            std::memcpy(&out.texels[first], t.image->rgba.data(), t.image->rgba.size());  // R in the low byte
        }
        // Image (s, t) = scale^-1 rotate(-angle) (uv - offset).
        double a = t.rotate_deg * M_PI / 180.0, c = std::cos(a), s = std::sin(a);
        glm::dvec2 row_s = glm::dvec2(c, s) / t.scale.x;
        glm::dvec2 row_t = glm::dvec2(-s, c) / t.scale.y;
        TextureInfo info{};
        info.to_image_s = vec4(float(row_s.x), float(row_s.y), float(-glm::dot(row_s, t.offset)), 0.0f);
        info.to_image_t = vec4(float(row_t.x), float(row_t.y), float(-glm::dot(row_t, t.offset)), 0.0f);
        info.texel_offset = at->second;
        info.width = static_cast<uint>(t.image->width);
        info.height = static_cast<uint>(t.image->height);
        info.flags = (t.wrap_u == TextureWrap::Clamp ? TEXTURE_CLAMP_U : 0u) |
                     (t.wrap_v == TextureWrap::Clamp ? TEXTURE_CLAMP_V : 0u) |
                     (t.filter == TextureFilter::Nearest ? TEXTURE_NEAREST : 0u);
        out.textures.push_back(info);
        return static_cast<uint>(out.textures.size() - 1);
    }

    uint pattern(const Pattern& p, double bump_amount) {
        PatternInfo info{};
        glm::dmat4 to_pattern = glm::inverse(p.to_world);  // column-major: m[column][row]
        vec4* rows[] = {&info.row0, &info.row1, &info.row2};
        for (int r = 0; r < 3; ++r)
            *rows[r] = vec4(float(to_pattern[0][r]), float(to_pattern[1][r]), float(to_pattern[2][r]), float(to_pattern[3][r]));
        double mean_scale = std::cbrt(std::abs(glm::determinant(glm::dmat3(p.to_world))));
        info.params = vec4(float(p.turbulence), float(p.omega), float(p.lambda), float(bump_amount * mean_scale));
        switch (p.type) {
            case PatternType::Noise: info.type = PATTERN_NOISE; break;
            case PatternType::Turbulence: info.type = PATTERN_TURBULENCE; break;
            case PatternType::Marble: info.type = PATTERN_MARBLE; break;
            case PatternType::Wood: info.type = PATTERN_WOOD; break;
        }
        info.octaves = static_cast<uint>(p.octaves);
        info.color_count = static_cast<uint>(p.colors.size());
        for (std::size_t i = 0; i < p.colors.size(); ++i) info.colors[i] = v4(p.colors[i].color, p.colors[i].position);
        out.patterns.push_back(info);
        return static_cast<uint>(out.patterns.size() - 1);
    }

    Material material(const lancer::Material& m) {
        Material g{};
        g.color = v4(m.checker ? m.checker->color_a : m.color);
        g.color2 = v4(m.checker ? m.checker->color_b : m.color);
        g.phong = vec4(float(m.ambient), float(m.diffuse), float(m.specular), float(m.shininess));
        g.reflection = float(m.reflection);
        g.pattern = m.checker ? PATTERN_CHECKER : PATTERN_SOLID;
        g.checker_size = m.checker ? float(m.checker->size) : 1.0f;
        g.checker_phase = m.checker ? v4(checker_phase(anchor, m.checker->size)) : vec4(0.0f);
        g.texture_map = m.texture ? texture(*m.texture) : NO_MAP;
        g.color_pattern = m.pattern ? pattern(*m.pattern, 0.0) : NO_MAP;
        g.bump_pattern = m.bump ? pattern(m.bump->pattern, m.bump->amount) : NO_MAP;
        g.model = MODEL_PHONG;
        g.energy_table = 0;
        g.transmission = v4(m.transmission, m.ior);
        g.absorption = v4(m.absorption);
        g.highlight = m.highlight == Highlight::Blinn ? HIGHLIGHT_BLINN : HIGHLIGHT_PHONG;
        if (m.microfacet()) microfacet(m, g);
        return g;
    }

    // A microfacet material's constants in the rows Phong's would use (layout.h, Material).
    void microfacet(const lancer::Material& m, Material& g) {
        const double alpha = m.alpha();
        g.model = m.conductor ? MODEL_MICROFACET_METAL : MODEL_MICROFACET_GLASS;
        g.color = v4(m.color);
        g.color2 = v4(m.conductor ? m.conductor->eta : dvec3(0.0), alpha);
        g.phong = v4(m.conductor ? m.conductor->k : dvec3(0.0), 1.0);
        g.reflection = 0.0f;
        g.pattern = PATTERN_SOLID;
        g.texture_map = g.color_pattern = g.bump_pattern = NO_MAP;
        if (!m.conductor || alpha == 0.0) return;
        // Rough metals: their table of E(mu) (one per roughness), E_avg and the multiple-
        // scattering colour, all from host/optics (the CPU reference reads the same table).
        auto found = tables.find(alpha);
        if (found == tables.end()) {
            optics::EnergyTable t = optics::ggx_energy(alpha);
            for (double e : t.e) out.energy_tables.push_back(std::bit_cast<uint>(float(e)));
            found = tables.emplace(alpha, std::pair{uint(tables.size()), t.e_avg}).first;
        }
        g.energy_table = found->second.first;
        const double e_avg = found->second.second;
        g.phong.w = float(e_avg);
        dvec3 tint = optics::multiple_scattering_tint(
            optics::conductor_fresnel_average(m.conductor->eta, m.conductor->k) * m.color, e_avg);
        g.ms_tint_r = float(tint.r);
        g.ms_tint_g = float(tint.g);
        g.ms_tint_b = float(tint.b);
    }
};

// Photon mapping's view of the lights (layout.h, Emitter): each photon's power and the
// cumulative probabilities by which photons choose a light (proportional to its power), as the
// CPU reference's photon tracer (host/cpu/photon_tracer.cpp).
void pack_emitters(const Scene& scene, PackedScene& out) {
    double total = 0.0;
    std::vector<dvec3> flux;
    for (const lancer::Light& l : scene.lights) {
        flux.push_back(radiant_flux(l).value_or(dvec3(0.0)));
        total += flux.back().r + flux.back().g + flux.back().b;
    }
    double cumulative = 0.0;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const lancer::Light& l = scene.lights[i];
        const double share = flux[i].r + flux[i].g + flux[i].b;
        cumulative += share;
        Emitter e{};
        // flux / (N P(light)), P(light) = share / total
        dvec3 power = share > 0.0 ? flux[i] * (total / share) / double(scene.photons->count) : dvec3(0.0);
        e.power = v4(power, total > 0.0 ? cumulative / total : 1.0);
        double cone = 1.0;
        if (l.type == LightType::Spot)
            cone = 2.0 * M_PI * (1.0 - std::cos(l.outer_angle_deg * M_PI / 180.0)) / spot_solid_angle(l);
        e.cone = vec4(float(cone), 0.0f, 0.0f, 0.0f);
        out.emitters.push_back(e);
    }
}

Light pack_light(const lancer::Light& l) {
    constexpr double kDegree = M_PI / 180.0;
    Light g{};
    g.position = v4(l.position, l.falloff == Falloff::InverseSquare ? l.falloff_distance : 0.0);
    g.color = v4(l.emitted());
    switch (l.type) {
        case LightType::Point: g.type = LIGHT_POINT; break;
        case LightType::Spot:
            g.type = LIGHT_SPOT;
            g.direction = v4(l.direction);
            g.spot = vec4(float(std::cos(l.outer_angle_deg * kDegree)), float(std::cos(l.inner_angle_deg * kDegree)),
                          float(l.tightness), 0.0f);
            break;
        case LightType::Area:
            g.type = LIGHT_AREA;
            g.edge_u = v4(l.edge_u);
            g.edge_v = v4(l.edge_v);
            g.samples = static_cast<uint>(l.samples);
            g.jitter = l.jitter ? 1u : 0u;
            break;
    }
    return g;
}

// The Bezier leaves of the whole scene, counted before any is made: a scene with too many for
// the device is refused before the packer spends seconds and gigabytes on them.
std::uint64_t bezier_leaf_count(const Scene& scene) {
    std::uint64_t leaves = 0;
    for (const Object& o : scene.objects)
        if (const auto* s = std::get_if<BezierSurface>(&o.shape)) leaves += std::uint64_t(s->patches.size()) << (2 * s->subdivision);
    return leaves;
}

}  // namespace

std::uint32_t photon_capacity(std::uint32_t count) {
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(2ull * count + 1024, 1u << 26));
}

std::uint32_t photon_buckets(std::uint32_t capacity) {
    return std::clamp(std::bit_ceil(capacity / 8), 1024u, 1u << 20);
}

float round_down(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

float round_up(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

PackedScene pack_scene(const Scene& world, const PackOptions& options) {
    if (options.limits) check_buffer_need(array_need(SceneArray::PATCHES, bezier_leaf_count(world)), *options.limits);
    PackedScene packed;
    packed.anchor = float_anchor(world.camera);
    packed.float_notes = float_resolution_notes(world, packed.anchor);
    std::optional<Scene> local;
    if (packed.anchor != dvec3(0.0)) local = rebased(world, packed.anchor);
    const Scene& scene = local ? *local : world;
    std::vector<std::pair<Primitive, std::optional<Aabb>>> prims;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        std::visit(PrimitivePacker{packed, prims, o.material, static_cast<uint>(i)}, o.shape);
    }
    const Acceleration acceleration = options.acceleration;
    std::size_t bounded_count = 0;
    for (const auto& [p, box] : prims) bounded_count += box.has_value();
    bool use_bvh = acceleration == Acceleration::BvhAlways ||
                   (acceleration == Acceleration::Bvh && bounded_count >= kMinPrimitivesForBvh);
    // Beside costly shapes (patches, expression surfaces) in a BVH, a few cheap bounded ones
    // stay outside it, tested by every ray in loops of their own: in the BVH's leaves, lavapipe
    // would run their code at every test of a patch or cell (the teapot 0.93x the time).
    std::size_t analytic = 0;
    bool expensive = false;
    for (const auto& [p, box] : prims) {
        if (!box) continue;
        analytic += shape_is_boxable(p.type);
        expensive |= !shape_has(p.type, SHAPE_CHEAP);
    }
    const bool analytic_outside = expensive && analytic <= kMaxAnalyticOutsideBvh;
    std::vector<Primitive> bounded;
    std::vector<std::pair<Primitive, std::optional<Aabb>>> unbounded;
    std::vector<Aabb> boxes;
    for (const auto& [p, box] : prims) {
        if (use_bvh && box && !(analytic_outside && shape_is_boxable(p.type))) {
            bounded.push_back(p);
            boxes.push_back(*box);
        } else {
            unbounded.emplace_back(p, box);
        }
    }
    Bvh built;
    const Bvh& bvh = options.cache ? options.cache->build(boxes) : (built = build_bvh(boxes));
    for (std::uint32_t index : bvh.order) packed.primitives.push_back(bounded[index]);
    // By family, so that the shader tests each family in a loop of its own (scene.glsl).
    std::stable_sort(unbounded.begin(), unbounded.end(), [](const auto& a, const auto& b) { return a.first.type < b.first.type; });
    Aabb everything;
    for (const auto& [p, box] : prims)
        if (box) everything.extend(*box);
    for (uint type = 0; type < SHAPE_COUNT; ++type) {
        if (!shape_is_boxable(type)) continue;
        auto begin = std::find_if(unbounded.begin(), unbounded.end(), [&](const auto& e) { return e.first.type == type; });
        auto end = std::find_if(begin, unbounded.end(), [&](const auto& e) { return e.first.type != type; });
        packed.families[type] = box_family(std::span(begin, end), everything);
    }
    for (const auto& e : unbounded) packed.primitives.push_back(e.first);
    packed.unbounded_count = static_cast<uint>(unbounded.size());
    for (const lancer::BvhNode& n : bvh.nodes) {
        gpu::BvhNode g{};
        pack_box(n.box, g.lo, g.hi);
        g.first = n.first;
        g.count = n.count;
        packed.nodes.push_back(g);
    }
    MapPacker maps{packed, {}, {}, packed.anchor};
    for (const lancer::Material& m : scene.materials) packed.materials.push_back(maps.material(m));
    if (!packed.patterns.empty()) packed.permutation.assign(kPerlinPermutation.begin(), kPerlinPermutation.end());
    for (const lancer::Light& l : scene.lights) packed.lights.push_back(pack_light(l));
    if (scene.photons) {
        pack_emitters(scene, packed);
        packed.photon_count = static_cast<uint>(scene.photons->count);
    }
    ShaderFeatures& f = packed.features;
    f.has_photons = scene.photons.has_value();
    const std::size_t in_bvh = packed.nodes.empty() ? 0 : packed.primitives.size() - packed.unbounded_count;
    f.bvh_has_analytic = false;
    for (std::size_t i = 0; i < in_bvh; ++i) f.bvh_has_analytic |= shape_is_boxable(packed.primitives[i].type);
    for (const Primitive& p : packed.primitives) f.add_shape(p.type);
    for (uint type = 0; type < SHAPE_COUNT; ++type) {
        if (packed.families[type].boxed) f.boxed_families |= 1u << type;
        if (packed.families[type].split) f.split_families |= 1u << type;
    }
    for (const PatchLeaf& leaf : packed.patches)
        for (const vec4& point : leaf.points) f.has_rational_patches |= point.w != 1.0f;
    f.has_bvh = !packed.nodes.empty();
    f.has_textures = !packed.textures.empty();
    f.has_patterns = !packed.patterns.empty();
    for (const lancer::Material& m : scene.materials) {
        f.has_transparency |= m.transparent();
        f.has_blinn |= m.highlight == Highlight::Blinn;
        f.has_microfacet |= m.microfacet();
    }
    for (const lancer::Light& l : scene.lights) {
        f.has_area_lights |= l.type == LightType::Area;
        f.has_spot_lights |= l.type == LightType::Spot;
        f.has_falloff |= l.falloff != Falloff::None;
    }
    // Direction grids for camera and shadow rays, where every shape is cheap to test (the
    // shader's CHEAP_SHAPES) and any hit blocks a shadow ray (no transparency).
    bool cheap = true;
    for (const Primitive& p : packed.primitives) cheap &= shape_has(p.type, SHAPE_CHEAP);
    f.direction_grids = f.has_bvh && cheap && !f.has_transparency;
    if (f.direction_grids) {
        std::vector<Aabb> packed_boxes;
        packed_boxes.reserve(bvh.order.size());
        for (std::uint32_t index : bvh.order) packed_boxes.push_back(boxes[index]);
        // The eye as the shader has it (pack_frame), so that camera rays start at the grid's origin.
        const CameraBasis cam = make_camera_basis(scene.camera, scene.render.width, scene.render.height);
        const vec4 eye = v4(cam.eye);
        // The first plane that is a flat mirror: its reflections of camera rays take a grid too.
        std::optional<Mirror> mirror;
        for (std::size_t i = packed.primitives.size() - packed.unbounded_count; i < packed.primitives.size() && !mirror; ++i) {
            const Primitive& p = packed.primitives[i];
            const lancer::Material& m = scene.materials[p.material];
            if (p.type != SHAPE_PLANE || !(m.reflection > 0.0) || m.microfacet() || m.bump) continue;
            mirror = Mirror{dvec3(p.p0.x, p.p0.y, p.p0.z), glm::normalize(dvec3(p.p1.x, p.p1.y, p.p1.z))};
            packed.mirror_plane = static_cast<uint>(i);
        }
        DirectionGrids grids = direction_grids({dvec3(eye.x, eye.y, eye.z), cam.forward, cam.right, cam.up},
                                               mirror ? &*mirror : nullptr, packed.lights, packed_boxes);
        // Where every ray takes a grid, the shader leaves the BVH's traversal out: camera rays,
        // the mirror's reflections of them (no other surface reflects: those reflections end at
        // their first hit) and shadow rays to point and spot lights, each light with its grid.
        auto valid = [&](uint k) { return grids.grids[k].valid != 0; };
        bool every_ray = valid(DIRECTION_GRID_EYE) && (!mirror || valid(DIRECTION_GRID_MIRROR)) && !f.has_photons &&
                         !f.has_microfacet && packed.lights.size() <= DIRECTION_GRID_COUNT - DIRECTION_GRID_LIGHT;
        for (std::size_t k = 0; k < packed.lights.size() && every_ray; ++k) every_ray = valid(DIRECTION_GRID_LIGHT + uint(k));
        for (std::size_t i = 0; i < packed.primitives.size() && every_ray; ++i)
            every_ray = !(scene.materials[packed.primitives[i].material].reflection > 0.0) || i == packed.mirror_plane;
        f.grids_only = every_ray;
        packed.grids = std::move(grids.grids);
        packed.grid_cells = std::move(grids.cells);
        packed.grid_entries = std::move(grids.entries);
    }
    return packed;
}

std::size_t PackedScene::count(SceneArray array) const {
    switch (array) {
#define LANCER_PACKED_COUNT(NAME, slot, kind, Element, member, reader, what) \
    case SceneArray::NAME: return member.size();
        LANCER_SCENE_ARRAYS(LANCER_PACKED_COUNT)
#undef LANCER_PACKED_COUNT
    }
    return 0;
}

std::span<const std::byte> PackedScene::bytes(SceneArray array) const {
    switch (array) {
#define LANCER_PACKED_BYTES(NAME, slot, kind, Element, member, reader, what) \
    case SceneArray::NAME: return std::as_bytes(std::span(member));
        LANCER_SCENE_ARRAYS(LANCER_PACKED_BYTES)
#undef LANCER_PACKED_BYTES
    }
    return {};
}

std::vector<BufferNeed> buffer_needs(const PackedScene& packed, std::uint64_t output_bytes) {
    std::vector<BufferNeed> needs;
    for (std::size_t a = 0; a < kSceneArrayCount; ++a)
        needs.push_back(array_need(SceneArray(a), packed.count(SceneArray(a))));
    needs.push_back({"output rows", RESOURCE_OUTPUT, output_bytes / sizeof(vec4), output_bytes});
    // A band of refined pixels (adaptive anti-aliasing) lists at most the band's pixels.
    needs.push_back({"pixels to refine", RESOURCE_OUTPUT, output_bytes / sizeof(vec4), output_bytes / sizeof(vec4) * sizeof(uint)});
    if (packed.features.has_photons) {
        // Photon mapping's buffers at the size a pass starts with (gpu/passes/photon_pass.cpp); a pass
        // that stores more grows them and is checked again there.
        const std::uint64_t photons = photon_capacity(packed.photon_count);
        needs.push_back({"photons", RESOURCE_OUTPUT, photons, photons * sizeof(Photon)});
        needs.push_back({"photons by grid bucket", RESOURCE_OUTPUT, photons, photons * sizeof(Photon)});
        const std::uint64_t buckets = 2ull * photon_buckets(photons);
        needs.push_back({"grid buckets", RESOURCE_OUTPUT, 2 * buckets + 1, (2 * buckets + 1) * sizeof(uint)});
    }
    return needs;
}

FrameParams pack_frame(const Scene& scene, const PackedScene& packed) {
    const RenderSettings& r = scene.render;
    CameraBasis cam = make_camera_basis(scene.camera, r.width, r.height);
    FrameParams f{};
    f.eye = v4(cam.eye - packed.anchor);
    f.forward = v4(cam.forward);
    f.right = v4(cam.right);
    f.up = v4(cam.up);
    f.background = v4(r.background);
    f.ambient = v4(scene.ambient);
    f.width = static_cast<uint>(r.width);
    f.height = static_cast<uint>(r.height);
    f.samples = static_cast<uint>(r.samples);
    f.max_depth = static_cast<uint>(r.max_depth);
    f.primitive_count = static_cast<uint>(packed.primitives.size());
    f.light_count = static_cast<uint>(packed.lights.size());
    f.node_count = static_cast<uint>(packed.nodes.size());
    f.unbounded_count = packed.unbounded_count;
    // Where each family of the unbounded primitives (sorted by type) ends, and the family boxes
    // (family_boxes.hpp): two per family, the second unused unless it is split.
    std::size_t i = packed.primitives.size() - packed.unbounded_count;
    for (uint type = 0; type < SHAPE_COUNT; ++type) {
        const uint begin = static_cast<uint>(i);
        while (i < packed.primitives.size() && packed.primitives[i].type <= type) ++i;
        f.family_end[type / 4][type % 4] = static_cast<uint>(i);
        f.family_split[type / 4][type % 4] = begin + packed.families[type].split_at;
        for (int h = 0; h < 2; ++h) {
            const Aabb& box = packed.families[type].halves[h];
            pack_box(box.empty() ? Aabb{dvec3(0.0), dvec3(0.0)} : box, f.family_lo[2 * type + h], f.family_hi[2 * type + h]);
        }
    }
    f.mirror_plane = packed.mirror_plane;
    f.loop_probe = 2;
    return f;
}

}  // namespace lancer::gpu

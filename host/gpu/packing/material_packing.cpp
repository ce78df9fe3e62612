#include "gpu/packing/material_packing.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <map>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "core/perlin_permutation.hpp"
#include "gpu/packing/float_anchor.hpp"
#include "gpu/packing/float_bounds.hpp"
#include "optics/energy.hpp"
#include "optics/ggx.hpp"
#include "scene/limits.hpp"

namespace lancer::gpu {
namespace {

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

    static void set_rows(PatternInfo& info, const glm::dmat4& to_pattern) {  // column-major: m[column][row]
        vec4* rows[] = {&info.row0, &info.row1, &info.row2};
        for (int r = 0; r < 3; ++r)
            *rows[r] = vec4(float(to_pattern[0][r]), float(to_pattern[1][r]), float(to_pattern[2][r]), float(to_pattern[3][r]));
    }

    // A checker's own transform, as a pattern's rows (appearance.glsl reads nothing else of it).
    uint frame(const glm::dmat4& to_checker) {
        PatternInfo info{};
        set_rows(info, to_checker);
        out.patterns.push_back(info);
        return static_cast<uint>(out.patterns.size() - 1);
    }

    uint pattern(const Pattern& p, double bump_amount) {
        PatternInfo info{};
        set_rows(info, glm::inverse(p.to_world));
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
        g.checker_frame = m.checker && m.checker->to_checker ? frame(*m.checker->to_checker) : NO_MAP;
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

}  // namespace

void pack_materials(const Scene& scene, const glm::dvec3& anchor, PackedScene& out) {
    MapPacker maps{out, {}, {}, anchor};
    for (const lancer::Material& m : scene.materials) out.materials.push_back(maps.material(m));
    if (scene.sky && scene.sky->pattern) out.sky_pattern = maps.pattern(*scene.sky->pattern, 0.0);
    if (!out.patterns.empty()) out.permutation.assign(kPerlinPermutation.begin(), kPerlinPermutation.end());
}

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
    g.position = v4(l.position, l.falloff != Falloff::None ? l.falloff_distance : 0.0);
    g.direction.w = l.falloff == Falloff::PovFade ? float(l.fade_power) : 0.0f;
    g.color = v4(l.emitted());
    switch (l.type) {
        case LightType::Point: g.type = LIGHT_POINT; break;
        case LightType::Spot:
            g.type = LIGHT_SPOT;
            g.direction = v4(l.direction, g.direction.w);
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

}  // namespace lancer::gpu

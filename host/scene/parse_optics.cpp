#include "scene/parse_optics.hpp"

#include <fmt/format.h>

#include "optics/metals.hpp"

namespace lancer {
namespace {

// A colour given as [r, g, b], or as one number for all three channels.
dvec3 color_or_scalar(TableReader& t, std::string_view key, dvec3 fallback) {
    const toml::node* node = t.node(key);
    if (!node) return fallback;
    if (node->is_number()) return dvec3(node_number(*node, t.file(), std::string(key)));
    return node_vec3(*node, t.file(), std::string(key));
}

// transmission, ior and absorption: what makes a material a dielectric that light goes through.
void read_transmission(TableReader& t, Material& m) {
    m.transmission = color_or_scalar(t, "transmission", m.transmission);
    for (int c = 0; c < 3; ++c) check_range(t, "transmission", m.transmission[c], 0.0, 1.0);
    if (t.has("ior")) {
        m.ior = t.number("ior", m.ior);
        if (!(m.ior > 0.0)) t.fail("ior", fmt::format("ior must be positive, not {:g}", m.ior));
        if (!m.transparent())
            t.fail("ior", "ior has no effect on an opaque material: give it a transmission above 0 as well");
    }
    if (t.has("absorption")) {
        m.absorption = check_color(t, "absorption", color_or_scalar(t, "absorption", m.absorption));
        if (!m.transparent())
            t.fail("absorption", "absorption has no effect on an opaque material: give it a transmission above 0 as well");
    }
}

const std::vector<std::string> kMicrofacetOnly = {"roughness", "metal", "eta", "k"};

// Below this, GGX's peak (1 / (pi alpha^2)) outgrows what float holds well on the GPU; 0 itself
// is the exact mirror.
constexpr double kMinRoughness = 0.01;

}  // namespace

const std::vector<std::string>& phong_only_keys() {
    static const std::vector<std::string> keys = {"ambient", "diffuse", "specular", "shininess", "reflection",
                                                  "highlight", "checker", "texture", "pattern", "bump"};
    return keys;
}

void read_optics(TableReader& t, Material& m) {
    for (const std::string& key : kMicrofacetOnly)
        if (t.has(key)) t.fail(key, fmt::format("{} is a key of microfacet materials (model = \"microfacet\")", key));
    read_transmission(t, m);
    m.highlight = static_cast<Highlight>(one_of(t, "highlight", "highlight", {"phong", "blinn"}, "phong"));
}

void read_microfacet(TableReader& t, Material& m) {
    for (const std::string& key : phong_only_keys())
        if (t.has(key))
            t.fail(key, fmt::format("{} is a key of Phong materials, not of microfacet ones (model = \"microfacet\")", key));
    m.color = check_color(t, "color", t.vec3("color", m.color));
    for (int c = 0; c < 3; ++c)
        if (m.color[c] > 1.0)
            t.fail("color", fmt::format("a microfacet material's color tints what it reflects and must be within "
                                        "[0, 1], not {:g}",
                                        m.color[c]));
    m.roughness = check_range(t, "roughness", t.number("roughness", 0.5), 0.0, 1.0);
    if (m.roughness > 0.0 && m.roughness < kMinRoughness)
        t.fail("roughness", fmt::format("roughness must be 0 (a perfect mirror) or at least {:g}, not {:g}",
                                        kMinRoughness, m.roughness));
    read_transmission(t, m);

    std::vector<std::string> metal_names;
    for (const optics::MetalPreset& p : optics::metal_presets()) metal_names.push_back(p.name);
    const bool metal = t.has("metal"), eta = t.has("eta"), k = t.has("k");
    if (metal && (eta || k)) t.fail(eta ? "eta" : "k", "give metal or eta and k, not both");
    if (eta != k) t.fail(eta ? "eta" : "k", "a conductor's complex index needs both eta and k");
    if (metal) {
        m.conductor = optics::metal_presets()[one_of(t, "metal", "metal", metal_names, "")].ior;
    } else if (eta) {
        optics::ComplexIor ior{check_color(t, "eta", color_or_scalar(t, "eta", dvec3(0.0))),
                               check_color(t, "k", color_or_scalar(t, "k", dvec3(0.0)))};
        for (int c = 0; c < 3; ++c)
            if (!(ior.eta[c] + ior.k[c] > 0.0)) t.fail("eta", "eta and k must not both be 0 (no interface)");
        m.conductor = ior;
    }
    if (m.conductor && m.transparent())
        t.fail("transmission", "a metal lets no light through: give it transmission or metal (eta and k), not both");
    if (!m.conductor && !m.transparent())
        t.fail("", "a microfacet material is a metal (metal = \"gold\", or eta and k) or a glass (transmission above 0)");
    if (!m.conductor && t.has("color"))
        t.fail("color", "color tints a metal; a glass takes its colour from transmission and absorption");
}

}  // namespace lancer

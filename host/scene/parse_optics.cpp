#include "scene/parse_optics.hpp"

#include <fmt/format.h>

namespace lancer {
namespace {

// A colour given as [r, g, b], or as one number for all three channels.
dvec3 color_or_scalar(TableReader& t, std::string_view key, dvec3 fallback) {
    const toml::node* node = t.node(key);
    if (!node) return fallback;
    if (node->is_number()) return dvec3(node_number(*node, t.file(), std::string(key)));
    return node_vec3(*node, t.file(), std::string(key));
}

}  // namespace

void read_optics(TableReader& t, Material& m) {
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
    m.highlight = static_cast<Highlight>(one_of(t, "highlight", "highlight", {"phong", "blinn"}, "phong"));
}

}  // namespace lancer

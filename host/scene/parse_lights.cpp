#include "scene/parse_lights.hpp"

#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "core/constants.hpp"
#include "scene/limits.hpp"
#include "scene/parse_shapes.hpp"

namespace lancer {
namespace {

const std::vector<std::string> kTypeNames = {"point", "spot", "area"};

// Keys that only one type of light takes.
struct TypeKeys {
    LightType type;
    std::vector<std::string> keys;
};
const TypeKeys kTypeKeys[] = {
    {LightType::Spot, {"point_at", "direction", "inner_angle", "outer_angle", "tightness"}},
    {LightType::Area, {"corner", "edge_u", "edge_v", "samples", "jitter"}},
};

// A key of another light type is an error that says which type takes it.
void reject_other_types_keys(TableReader& t, LightType type) {
    for (const TypeKeys& k : kTypeKeys) {
        if (k.type == type) continue;
        for (const std::string& key : k.keys)
            if (t.has(key))
                t.fail(key, fmt::format("{} is a key of {} lights (type = \"{}\"), not of {} lights", key,
                                        kTypeNames[int(k.type)], kTypeNames[int(k.type)], kTypeNames[int(type)]));
    }
}

// power (W) or intensity (W/sr): a light in physical units, which falls off with the square of
// the distance. `color` stays a tint; the size goes into Light::scale, in the renderer's units
// (radiant_flux in scene.hpp): the colour at distance 1 is intensity / pi.
void read_radiometry(TableReader& t, Light& l) {
    const bool power = t.has("power"), intensity = t.has("intensity");
    if (!power && !intensity) return;
    const char* key = power ? "power" : "intensity";
    if (power && intensity) t.fail("intensity", "give power or intensity, not both");
    for (const char* other : {"falloff", "falloff_distance"})
        if (t.has(other))
            t.fail(other, fmt::format("{} is not used with {}: a light in physical units falls off with the square "
                                      "of the distance",
                                      other, key));
    double value = t.number(key, 0.0);
    if (!(value > 0.0)) t.fail(key, fmt::format("{} must be positive, not {:g}", key, value));
    // Watts spread over the solid angle the light covers (a spot's cone, weighted by its edge).
    double solid_angle = l.type == LightType::Spot ? spot_solid_angle(l) : 4.0 * kPi;
    double watts_per_sr = power ? value / solid_angle : value;
    l.falloff = Falloff::InverseSquare;
    l.falloff_distance = 1.0;
    l.scale = watts_per_sr / kPi;
}

// POV-Ray's light fading, with its words and formula: 2 / (1 + (d / fade_distance)^fade_power),
// 1 at fade_distance, 2 at the light, for any positive fade_power (1 linear, 2 quadratic).
void read_pov_fade(TableReader& t, Light& l) {
    for (const char* other : {"falloff", "falloff_distance", "power", "intensity"})
        if (t.has(other))
            t.fail(other, fmt::format("{} is not used with fade_distance and fade_power (POV-Ray's fading): give one "
                                      "way of falling off",
                                      other));
    if (!t.has("fade_distance") || !t.has("fade_power"))
        t.fail(t.has("fade_distance") ? "fade_distance" : "fade_power",
               "POV-Ray's fading needs both fade_distance and fade_power: the light is 2 / (1 + (d / fade_distance)"
               "^fade_power) times its color at distance d");
    l.falloff = Falloff::PovFade;
    l.falloff_distance = t.number("fade_distance", 1.0);
    if (!(l.falloff_distance > 0.0))
        t.fail("fade_distance", fmt::format("fade_distance must be positive, not {:g}", l.falloff_distance));
    l.fade_power = t.number("fade_power", 1.0);
    if (!(l.fade_power > 0.0 && l.fade_power <= 100.0))
        t.fail("fade_power", fmt::format("fade_power must be in (0, 100], not {:g} (0 is no fading: leave both keys "
                                         "out)",
                                         l.fade_power));
}

void read_falloff(TableReader& t, Light& l) {
    if (t.has("fade_distance") || t.has("fade_power")) return read_pov_fade(t, l);
    if (t.has("power") || t.has("intensity")) return;  // read_radiometry
    l.falloff = static_cast<Falloff>(one_of(t, "falloff", "falloff", {"none", "inverse_square"}, "none"));
    if (l.falloff == Falloff::InverseSquare) {
        if (!t.has("falloff_distance"))
            t.fail("falloff", "falloff = \"inverse_square\" needs falloff_distance, the distance at which the light "
                              "has its color");
        l.falloff_distance = t.number("falloff_distance", l.falloff_distance);
        if (!(l.falloff_distance > 0.0))
            t.fail("falloff_distance", fmt::format("falloff_distance must be positive, not {:g}", l.falloff_distance));
    } else if (t.has("falloff_distance")) {
        t.fail("falloff_distance", "falloff_distance needs falloff = \"inverse_square\"");
    }
}

void read_spot(TableReader& t, Light& l) {
    l.position = t.required_vec3("position");
    if (t.has("point_at") == t.has("direction"))
        t.fail(t.has("point_at") ? "direction" : "",
               t.has("point_at") ? "give point_at or direction, not both"
                                 : "[[light]]: a spot light needs point_at (a point it aims at) or direction");
    if (t.has("point_at")) {
        l.point_at = t.vec3("point_at", dvec3(0.0));
        if (!(glm::length(*l.point_at - l.position) > 0.0)) t.fail("point_at", "point_at must differ from position");
        aim_spot(l);
    } else {
        dvec3 d = t.vec3("direction", dvec3(0.0));
        if (!(glm::length(d) > 0.0)) t.fail("direction", "direction must not be the zero vector");
        l.direction = glm::normalize(d);
    }
    l.outer_angle_deg = t.number("outer_angle", l.outer_angle_deg);
    if (!(l.outer_angle_deg > 0.0 && l.outer_angle_deg <= 90.0))
        t.fail("outer_angle", fmt::format("outer_angle must be in (0, 90] degrees, not {:g}", l.outer_angle_deg));
    l.inner_angle_deg = t.number("inner_angle", std::min(l.inner_angle_deg, l.outer_angle_deg));
    if (!(l.inner_angle_deg >= 0.0 && l.inner_angle_deg <= l.outer_angle_deg))
        t.fail("inner_angle", fmt::format("inner_angle must be in [0, outer_angle = {:g}] degrees, not {:g}",
                                          l.outer_angle_deg, l.inner_angle_deg));
    l.tightness = t.number("tightness", l.tightness);
    if (!(l.tightness >= 0.0)) t.fail("tightness", fmt::format("tightness must not be negative, not {:g}", l.tightness));
}

void read_area(TableReader& t, Light& l) {
    if (t.has("corner") == t.has("position"))
        t.fail(t.has("corner") ? "corner" : "",
               t.has("corner") ? "give corner or position (the centre), not both"
                               : "[[light]]: an area light needs position (its centre) or corner");
    read_edges(t, "area light", l.edge_u, l.edge_v);
    // The centre is what moves in animations; a corner is turned into it.
    l.position = t.has("corner") ? t.vec3("corner", dvec3(0.0)) + 0.5 * (l.edge_u + l.edge_v) : t.vec3("position", dvec3(0.0));
    l.samples = check_int_range(t, "samples", t.integer("samples", l.samples), 1, limits::kMaxAreaLightSamples);
    l.jitter = t.boolean("jitter", l.jitter);
}

}  // namespace

Light read_light(TableReader& t) {
    Light l;
    l.where = t.location();
    l.type = static_cast<LightType>(one_of(t, "type", "light type", kTypeNames, "point"));
    l.color = check_color(t, "color", t.vec3("color", l.color));
    l.name = t.string("name", "");
    reject_other_types_keys(t, l.type);
    read_falloff(t, l);
    switch (l.type) {
        case LightType::Point: l.position = t.required_vec3("position"); break;
        case LightType::Spot: read_spot(t, l); break;
        case LightType::Area: read_area(t, l); break;
    }
    read_radiometry(t, l);  // after the spot's cone, which its power spreads over
    t.finish();
    return l;
}

}  // namespace lancer

// POV-Ray's superellipsoid and blob, read as the implicit surfaces they are: the function is
// written from their parameters and goes through every check of `implicit` (parse_implicit.cpp),
// so both backends draw them exactly as they draw any implicit surface (certified roots on the
// CPU, interval search and Newton on the GPU).
//
//   type = "superellipsoid"   e = 0.25   n = 0.5
//       POV-Ray's superellipsoid { <e, n> }: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1, in [-1, 1]^3
//   type = "blob"   threshold = 0.6
//   spheres = [{ center = [0, 0, 0], radius = 1, strength = 1 }, ...]
//   cylinders = [{ base_point = [-1, 0, 0], cap_point = [1, 0, 0], radius = 0.5, strength = 1 }, ...]
//       POV-Ray's blob: the field of each component is strength (1 - d^2 / radius^2)^2 within
//       radius of its centre (or of its segment: a cylinder with round ends), 0 beyond; the
//       surface is where the fields' sum is the threshold, the inside where it is more.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "scene/parse_surfaces.hpp"
#include "surface/expr/parser.hpp"
#include "surface/polynomial.hpp"

namespace lancer {
namespace {

std::string number(double v) { return fmt::format("({:.17g})", v); }

bool is_whole(double v) { return std::round(v) == v; }

// f from text that lancer wrote: an error in it is lancer's, reported at the object's keys.
surface::Expr parse_written(TableReader& t, const std::string& key, const std::string& text) {
    try {
        return surface::parse_expression(text, {}, surface::kImplicitVariables);
    } catch (const surface::ExprError& e) {
        t.fail(key, t.what() + ": " + e.what());
    }
}

}  // namespace

// e and n within [0.001, 2]: toward 0 the shape becomes the cube (exponents up to 2000, still
// within float in its box: 1.01^2000 is 4e8); at 2 its edges are straight (the octahedron's);
// beyond, cusps whose gradient is infinite on the axes, which the searches are not proved for.
Shape read_superellipsoid(TableReader& t, const glm::dmat4& to_world) {
    auto exponent = [&](const char* key) {
        const double v = t.required_number(key);
        if (!(v >= 0.001 && v <= 2.0))
            t.fail(key, fmt::format("superellipsoid {} must be in [0.001, 2], not {:g} (0.001 is the cube to 0.06% of its "
                                    "size; beyond 2 the surface has cusps on its axes, which lancer does not draw)",
                                    key, v));
        return v;
    };
    const double e = exponent("e"), n = exponent("n");
    // A polynomial where the exponents allow (even powers, a whole outer power, degree <= 24:
    // e = n = 1 is the sphere x^2 + y^2 + z^2 = 1): the CPU reference then finds its roots as a
    // polynomial's. Otherwise powers of |x|, |y|, |z|.
    const double p = 2.0 / e, q = 2.0 / n, k = e / n;
    const bool polynomial = is_whole(p / 2.0) && is_whole(q / 2.0) && is_whole(k) && p * k <= surface::kMaxPolynomialDegree &&
                            q <= surface::kMaxPolynomialDegree;
    auto power = [&](char v, double exponent) {
        return polynomial ? fmt::format("{}^{}", v, exponent) : fmt::format("abs({})^{}", v, number(exponent));
    };
    std::string xy = fmt::format("({} + {})", power('x', p), power('y', p));
    if (k != 1.0) xy += "^" + (polynomial ? fmt::format("{}", k) : number(k));
    const std::string text = fmt::format("{} + {} - 1", xy, power('z', q));
    ImplicitObject object;
    object.surface.f = parse_written(t, "e", text);
    object.surface.box_lo = dvec3(-1.01);  // the surface reaches +-1: the box keeps it inside, closed
    object.surface.box_hi = dvec3(1.01);
    const SourceLocation at = t.location("e");
    return prepared_implicit(t, std::move(object), "e", [at](int) { return at; }, to_world);
}

namespace {

struct BlobComponent {
    dvec3 a, b;  // a sphere's centre (a == b), or a cylinder's segment
    double radius, strength;
};

std::vector<BlobComponent> read_components(TableReader& t, const char* key, bool cylinder) {
    std::vector<BlobComponent> out;
    const toml::array* list = t.array(key);
    if (!list) return out;
    for (std::size_t i = 0; i < list->size(); ++i) {
        const toml::table* table = list->get(i)->as_table();
        const std::string what = fmt::format("{} {}[{}]", t.what(), key, i);
        if (!table) throw SceneError(location_of(*list->get(i), t.file()), what + ": expected a table { ... }");
        TableReader c(*table, t.file(), what);
        BlobComponent k;
        if (cylinder) {
            k.a = c.required_vec3("base_point");
            k.b = c.required_vec3("cap_point");
            if (!(glm::length(k.b - k.a) > 0.0)) c.fail("cap_point", what + ": base_point and cap_point are the same point");
        } else {
            k.a = k.b = c.required_vec3("center");
        }
        k.radius = c.required_number("radius");
        if (!(k.radius > 0.0)) c.fail("radius", fmt::format("{}: radius must be positive, not {:g}", what, k.radius));
        k.strength = c.required_number("strength");
        if (!(k.strength != 0.0)) c.fail("strength", what + ": a strength of 0 adds nothing");
        c.finish();
        out.push_back(k);
    }
    return out;
}

// strength (1 - d^2 / r^2)^2 within r, as POV-Ray's blob; d from the centre, or from the segment.
std::string component_field(const BlobComponent& k) {
    const std::string px = fmt::format("(x - {})", number(k.a.x)), py = fmt::format("(y - {})", number(k.a.y)),
                      pz = fmt::format("(z - {})", number(k.a.z));
    std::string d2;
    if (k.a == k.b) {
        d2 = fmt::format("({}^2 + {}^2 + {}^2)", px, py, pz);
    } else {
        const dvec3 u = k.b - k.a;
        const dvec3 w = u / glm::dot(u, u);
        const std::string h = fmt::format("min(max({}*{} + {}*{} + {}*{}, 0), 1)", px, number(w.x), py, number(w.y), pz,
                                          number(w.z));
        d2 = fmt::format("(({} - {}*{})^2 + ({} - {}*{})^2 + ({} - {}*{})^2)", px, h, number(u.x), py, h, number(u.y), pz,
                         h, number(u.z));
    }
    return fmt::format("{}*max(0, 1 - {}/{})^2", number(k.strength), d2, number(k.radius * k.radius));
}

}  // namespace

Shape read_blob(TableReader& t, const glm::dmat4& to_world) {
    const double threshold = t.required_number("threshold");
    if (!(threshold > 0.0))
        t.fail("threshold", fmt::format("blob threshold must be positive, not {:g} (the field is 0 far from every "
                                        "component: a threshold of 0 or less would fill space)",
                                        threshold));
    std::vector<BlobComponent> components = read_components(t, "spheres", false);
    for (const BlobComponent& k : read_components(t, "cylinders", true)) components.push_back(k);
    if (components.empty())
        throw SceneError(t.location(), t.what() + ": a blob needs components: spheres = [{ center, radius, strength "
                                                  "}, ...] or cylinders = [{ base_point, cap_point, radius, strength }, ...]");
    // The surface lies where positive fields reach the threshold: within their components.
    dvec3 lo(std::numeric_limits<double>::infinity()), hi = -lo;
    std::string text = number(threshold);
    for (const BlobComponent& k : components) {
        text += " - " + component_field(k);
        if (k.strength > 0.0) {
            lo = glm::min(lo, glm::min(k.a, k.b) - k.radius);
            hi = glm::max(hi, glm::max(k.a, k.b) + k.radius);
        }
    }
    if (!(lo.x < hi.x))
        t.fail("threshold", t.what() + ": every component's strength is negative: the field never reaches the threshold");
    const dvec3 margin = 0.01 * (hi - lo);
    ImplicitObject object;
    object.surface.f = parse_written(t, "threshold", text);
    object.surface.box_lo = lo - margin;
    object.surface.box_hi = hi + margin;
    const SourceLocation at = t.location("threshold");
    return prepared_implicit(t, std::move(object), "threshold", [at](int) { return at; }, to_world);
}

bool is_implicit_type(std::string_view type) { return type == "implicit" || type == "superellipsoid" || type == "blob"; }

}  // namespace lancer

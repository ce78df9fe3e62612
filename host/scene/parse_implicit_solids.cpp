// POV-Ray's superellipsoid, read as the implicit surface it is: the function is written from
// its parameters and goes through every check of `implicit` (parse_implicit.cpp),
// so both backends draw it exactly as they draw any implicit surface (certified roots on the
// CPU, interval search and Newton on the GPU).
//
//   type = "superellipsoid"   e = 0.25   n = 0.5
//       POV-Ray's superellipsoid { <e, n> }: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1, in [-1, 1]^3
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

bool is_implicit_type(std::string_view type) { return type == "implicit" || type == "superellipsoid"; }

}  // namespace lancer

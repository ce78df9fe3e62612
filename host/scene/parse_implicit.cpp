// [[object]] type = "implicit": the surface f(x, y, z) = 0, clipped to a box of its own
// coordinates, with named constants, a transform and a material:
//   function = "(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + z^2)"
//   box = { min = [-1.4, -0.4, -1.4], max = [1.4, 0.4, 1.4] }   params = { R = 1, r = 0.35 }
// or, in place of `function`, POV-Ray's poly (quartic, cubic) coefficients in its order:
//   poly = [1, 0, 0, 0, 2, ...]                                 (35 numbers: degree 4)
// Errors inside the function point at their exact column in the scene file; a function that is
// undefined or infinite everywhere in the box, a polynomial above the degree limit, an empty box
// a constant beyond float's range, a function whose float evaluation overflows or strays from
// double's (the GPU evaluates f in float), a function above the operation limit and a surface
// that provably does not meet its box, or whose zeros fill a region or a face of the box, are
// errors too.
#include <array>
#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "scene/expression_keys.hpp"
#include "scene/limits.hpp"
#include "scene/parse_surfaces.hpp"
#include "surface/expr/domain_check.hpp"
#include "surface/expr/evaluate.hpp"
#include "surface/float_check.hpp"

namespace lancer {
namespace {

void read_box(TableReader& object, surface::ImplicitSurface& s) {
    const toml::table* box = object.table("box");
    if (!box)
        throw SceneError(object.location(), object.what() + ": missing required key 'box' (the box the surface is "
                                                             "clipped to, in its own coordinates, e.g. box = { min = "
                                                             "[-1, -1, -1], max = [1, 1, 1] })");
    TableReader b(*box, object.file(), object.what() + " box");
    s.box_lo = b.required_vec3("min");
    s.box_hi = b.required_vec3("max");
    b.finish();
    for (int i = 0; i < 3; ++i)
        if (!(s.box_lo[i] < s.box_hi[i]))
            b.fail("max", fmt::format("{}: the box is empty: max must be greater than min on every axis ({}: {:g} is "
                                      "not greater than {:g})",
                                      object.what(), "xyz"[i], s.box_hi[i], s.box_lo[i]));
}

// Where f is undefined or infinite everywhere in the box, the error is at the operation that
// makes it so.
void check_defined(const ColumnPlace& place, const surface::ImplicitSurface& s) {
    const surface::Interval box[] = {{s.box_lo.x, s.box_hi.x}, {s.box_lo.y, s.box_hi.y}, {s.box_lo.z, s.box_hi.z}};
    try {
        surface::check_expression_domain(s.f, box);
    } catch (const surface::ExprError& e) {
        throw SceneError(place(e.column), e.what());
    }
    if (auto origin = surface::where_non_finite_starts(s.f, box)) throw SceneError(place(origin->column), origin->what());
    try {
        surface::check_float_constants(s.f);  // the GPU evaluates f in float
    } catch (const surface::ExprError& e) {
        throw SceneError(place(e.column), e.what());
    }
}

// POV-Ray's poly { N, <c...> } (quartic: N = 4, cubic: 3) as the function it stands for. Its
// C(N + 3, 3) coefficients go with the monomials x^i y^j z^k, i + j + k <= N, ordered by i, then
// j, then k, each from the highest down (x^4, x^3 y, x^3 z, x^3, x^2 y^2, ... , z, 1).
std::string poly_function(TableReader& t) {
    const toml::array* list = t.array("poly");
    int order = 0;
    while (order < surface::kMaxPolynomialDegree && (order + 1) * (order + 2) * (order + 3) / 6 < int(list->size())) ++order;
    if ((order + 1) * (order + 2) * (order + 3) / 6 != int(list->size()) || order == 0)
        t.fail("poly", fmt::format("poly holds {} coefficients; POV-Ray's poly of degree N has (N + 1)(N + 2)(N + 3) / 6 "
                                   "(cubic 20, quartic 35, degree 5: 56), up to degree {}",
                                   list->size(), surface::kMaxPolynomialDegree));
    std::string text;
    std::size_t k = 0;
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int l = order - i - j; l >= 0; --l) {
                const std::size_t index = k++;
                const double c = node_number(*list->get(index), t.file(), fmt::format("poly[{}]", index));
                if (c == 0.0) continue;
                text += fmt::format("{}({:.17g})", text.empty() ? "" : " + ", c);
                for (const auto& [variable, power] : {std::pair{'x', i}, {'y', j}, {'z', l}})
                    if (power > 0) text += power == 1 ? fmt::format("*{}", variable) : fmt::format("*{}^{}", variable, power);
            }
    if (text.empty()) t.fail("poly", t.what() + ": every coefficient is 0: the surface would fill its whole box");
    return text;
}

}  // namespace

Shape read_implicit(TableReader& t, const glm::dmat4& to_world) {
    surface::Constants constants = read_params(t, surface::kImplicitVariables);
    ImplicitObject object;
    surface::ImplicitSurface& s = *object.surface;
    const toml::node* node = t.node("function");
    const bool poly = t.has("poly");
    if (node && poly) t.fail("poly", t.what() + ": give either function or poly (POV-Ray's coefficients), not both");
    if (!node && !poly)
        throw SceneError(t.location(), t.what() + ": missing required key 'function' (an expression in x, y and z: "
                                                  "the surface is where it is 0), or POV-Ray's poly coefficients");
    const std::string key = poly ? "poly" : "function";
    const ColumnPlace place = [&](int column) { return poly ? t.location("poly") : column_in_string(*node, t.file(), column); };
    if (poly) {
        const std::string text = poly_function(t);
        try {
            s.f = surface::parse_expression(text, constants, surface::kImplicitVariables);
        } catch (const surface::ExprError& e) {
            t.fail("poly", e.what());
        }
    } else {
        s.f = parse_expression_key(*node, t.file(), "function", constants, surface::kImplicitVariables);
    }
    read_box(t, s);
    return prepared_implicit(t, std::move(object), key, place, to_world);
}

Shape prepared_implicit(TableReader& t, ImplicitObject object, const std::string& key, const ColumnPlace& place,
                        const glm::dmat4& to_world) {
    surface::ImplicitSurface& s = *object.surface;
    check_defined(place, s);
    try {
        s.polynomial = surface::expand_polynomial(s.f);
    } catch (const surface::ExprError& e) {
        throw SceneError(place(e.column), e.what());
    }
    const surface::Expr* f[] = {&s.f};
    s.program = surface::compile_program(f);
    // Cost in operations after simplification, as for parametric surfaces: f becomes interval
    // and Newton code in the GPU's tracer, run at every step of every ray.
    if (const int operations = surface::count_operations(s.program); operations > limits::kMaxSurfaceOperations)
        t.fail(key, fmt::format("the function takes {} operations (after simplification); the limit is {}: it "
                                       "becomes code that the GPU's driver compiles and runs at every step of every ray",
                                       operations, limits::kMaxSurfaceOperations));
    try {
        surface::check_float_evaluation(s);  // the GPU finds and shades the zeros of f in float
    } catch (const surface::FloatEvaluationError& e) {
        throw SceneError(place(e.column), e.what());
    }
    if (s.polynomial && s.polynomial->degree() <= 0) {
        double c = s.polynomial->terms.empty() ? 0.0 : s.polynomial->terms.front().coefficient;
        t.fail(key, t.what() + (c == 0.0 ? ": the function is 0 everywhere: the surface would fill its whole box"
                                                : fmt::format(": the function is the constant {:g}: it is 0 nowhere", c)));
    }
    if (std::optional<std::string> degenerate = surface::degenerate_zero_set(s))
        t.fail(key, t.what() + ": " + *degenerate);
    s.place(to_world);
    if (surface::proved_without_zero(s)) {
        dvec3 centre = 0.5 * (s.box_lo + s.box_hi);
        const double xyz[] = {centre.x, centre.y, centre.z};
        double value = surface::evaluate<double>(s.f, xyz);
        t.fail(key, fmt::format("{}: the function is never 0 in the box (it keeps one sign there; {:g} at the "
                                       "box's centre): there is no surface to draw",
                                       t.what(), value));
    }
    dvec3 lo, hi;
    surface::implicit_world_bounds(s, lo, hi);
    check_world_extent(t, t.has("transform") ? "transform" : "box", lo, hi);
    std::array<dvec3, 2> search{s.box_lo, s.box_hi};
    surface::shrink_to_surface(s, search[0], search[1]);
    s.search_box = search;
    return object;
}

bool is_implicit_type(std::string_view type) { return type == "implicit"; }

}  // namespace lancer

// [[object]] type = "parametric": a surface given by its equations, x(u, v), y(u, v), z(u, v),
// over u = [u0, u1], v = [v0, v1], with named constants, a transform and a material:
//   x = "(R + r*cos(v))*cos(u)"   y = "r*sin(v)"   z = "(R + r*cos(v))*sin(u)"
//   u = [0, "2*pi"]   v = [0, "2*pi"]   params = { R = 1, r = 0.35 }
// Errors inside an expression point at its exact column in the scene file.
#include <limits>

#include <fmt/format.h>
#include <glm/common.hpp>

#include "core/magnitude.hpp"
#include "scene/expression_keys.hpp"
#include "scene/limits.hpp"
#include "scene/parse_surfaces.hpp"
#include "scene/string_position.hpp"
#include "surface/expr/domain_check.hpp"
#include "surface/expr/evaluate.hpp"
#include "surface/expr/parser.hpp"
#include "surface/float_check.hpp"
#include "surface/parametric_cells.hpp"

namespace lancer {
namespace {

// A domain bound: a number, or a constant expression such as "2*pi" (u and v are 0 there, and
// an expression that uses them is refused).
double read_bound(const toml::node& node, const std::string& file, const std::string& what,
                  const surface::Constants& constants) {
    if (!node.is_string()) return node_number(node, file, what);
    surface::Expr e = parse_expression_key(node, file, what, constants);
    for (const auto& n : e.nodes)
        if (n.op == surface::Op::Variable)
            throw SceneError(column_in_string(node, file, n.column), what + " must not depend on u or v");
    double value = surface::evaluate(e, 0.0, 0.0);
    if (!std::isfinite(value)) throw SceneError(location_of(node, file), what + " is not a finite number");
    if (std::abs(value) > kMaxMagnitude)
        throw SceneError(location_of(node, file), fmt::format("{} is {:g}, beyond lancer's limit of {:g} for any number",
                                                              what, value, kMaxMagnitude));
    return value;
}

std::pair<double, double> read_range(TableReader& t, std::string_view key, const surface::Constants& constants) {
    const toml::node* node = t.node(key);
    if (!node) t.fail(key, fmt::format("missing required key '{}' (its range, e.g. {} = [0, \"2*pi\"])", key, key));
    const toml::array* range = node->as_array();
    if (!range || range->size() != 2) t.fail(key, fmt::format("{} must be [start, end]", key));
    double lo = read_bound(*range->get(0), t.file(), std::string(key) + "[0]", constants);
    double hi = read_bound(*range->get(1), t.file(), std::string(key) + "[1]", constants);
    if (!(lo < hi)) t.fail(key, fmt::format("{} range is empty: {:g} is not less than {:g}", key, lo, hi));
    return {lo, hi};
}

}  // namespace

Shape read_parametric(TableReader& t, const glm::dmat4& to_world) {
    surface::Constants constants = read_params(t, surface::kParametricVariables);
    ParametricObject object;
    surface::ParametricSurface& s = *object.surface;
    const char* axes[] = {"x", "y", "z"};
    surface::Expr* exprs[] = {&s.x, &s.y, &s.z};
    for (int i = 0; i < 3; ++i) {
        const toml::node* node = t.node(axes[i]);
        if (!node) throw SceneError(t.location(), fmt::format("missing required key '{}' (an expression in u and v)", axes[i]));
        *exprs[i] = parse_expression_key(*node, t.file(), axes[i], constants);
    }
    // Cost in operations, not characters: "u*v*u*v*..." is 2,047 multiplications in 4,096
    // characters, and sin(u)+sin(u) one sine.
    {
        const surface::Expr* xyz[] = {&s.x, &s.y, &s.z};
        const int operations = surface::count_operations(surface::compile_program(xyz));
        if (operations > limits::kMaxSurfaceOperations) {
            int largest = 0, most = 0;
            for (int i = 0; i < 3; ++i) {
                const surface::Expr* one[] = {exprs[i]};
                int n = surface::count_operations(surface::compile_program(one));
                if (n > most) most = n, largest = i;
            }
            t.fail(axes[largest], fmt::format("the surface's equations take {} operations (x, y and z together, after "
                                              "simplification); the limit is {}: each becomes code that the GPU's driver "
                                              "compiles and runs at every step of every ray",
                                              operations, limits::kMaxSurfaceOperations));
        }
    }
    std::tie(s.u0, s.u1) = read_range(t, "u", constants);
    std::tie(s.v0, s.v1) = read_range(t, "v", constants);
    for (int i = 0; i < 3; ++i) {
        try {
            surface::check_expression_domain(*exprs[i], {s.u0, s.u1}, {s.v0, s.v1});
            // Infinite in double already (1e308*1e308): that error, at the operation, comes first.
            if (auto origin = surface::where_non_finite_starts(*exprs[i], {s.u0, s.u1}, {s.v0, s.v1})) throw *origin;
            surface::check_float_constants(*exprs[i]);
        } catch (const surface::ExprError& e) {
            throw SceneError(column_in_string(*t.node(axes[i]), t.file(), e.column), e.what());
        }
    }
    s.to_world = to_world;
    std::shared_ptr<const std::vector<surface::SurfaceCell>> cells;
    try {
        // The loader proves the surface can be cut into the GPU's cells (and bounds it by them);
        // the scene does not carry them: the GPU's packer asks again, and surface_cells keeps
        // them for it.
        cells = surface::surface_cells(s);
    } catch (const surface::FloatEvaluationError& e) {
        throw SceneError(column_in_string(*t.node(axes[e.expression]), t.file(), e.column), e.what());
    } catch (const UserError& e) {
        // Nowhere finite: point at the operation where that starts, if one expression shows it.
        for (int i = 0; i < 3; ++i)
            if (auto origin = surface::where_non_finite_starts(*exprs[i], {s.u0, s.u1}, {s.v0, s.v1}))
                throw SceneError(column_in_string(*t.node(axes[i]), t.file(), origin->column), origin->what());
        throw SceneError(t.location(), std::string("parametric surface: ") + e.what());
    }
    dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const auto& cell : *cells) {
        lo = glm::min(lo, cell.lo);
        hi = glm::max(hi, cell.hi);
    }
    check_world_extent(t, t.has("transform") ? "transform" : "x", lo, hi);
    object.bounds_lo = lo;
    object.bounds_hi = hi;
    if (t.boolean("closed", false)) {
        constexpr int n = 32;
        surface::SampledPatch grid{n, {}};
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
                grid.points.push_back(surface::evaluate_surface(s, s.u0 + (s.u1 - s.u0) * i / n, s.v0 + (s.v1 - s.v0) * j / n).P);
        object.outward = outward_side_of_declared(t, {grid});
    }
    return object;
}

int outward_side_of_declared(TableReader& t, const std::vector<surface::SampledPatch>& samples) {
    try {
        return surface::outward_side(samples);
    } catch (const UserError& e) {
        t.fail("closed", fmt::format("{}: declared closed, but {}", t.what(), e.what()));
    }
}

void check_world_extent(TableReader& t, std::string_view key, const dvec3& lo, const dvec3& hi) {
    for (int i = 0; i < 3; ++i) {
        double reach = std::max(std::abs(lo[i]), std::abs(hi[i]));
        if (!(reach <= kMaxMagnitude))
            t.fail(key, fmt::format("{}: the surface reaches {:g} on the {} axis, beyond lancer's limit of {:g} for "
                                    "any coordinate", t.what(), reach, "xyz"[i], kMaxMagnitude));
    }
}

}  // namespace lancer

#include "surface/float_check.hpp"

#include <array>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "surface/expr/gpu_float.hpp"

namespace lancer::surface {
namespace {

constexpr double kTolerance = 1e-3;  // of the surface's size

bool finite(const Dual<double>& d) { return std::isfinite(d.v) && std::isfinite(d.du) && std::isfinite(d.dv); }
bool finite(const Dual<GpuFloat>& d) { return std::isfinite(d.v.x) && std::isfinite(d.du.x) && std::isfinite(d.dv.x); }

std::string at_point(double u, double v) { return fmt::format("at (u, v) = ({:.6g}, {:.6g})", u, v); }

// Throws at the first operation whose float result gives out where double's does not; where()
// names the point (called only then).
template <class Where>
void check_no_overflow(const Program& program, const std::vector<Dual<double>>& exact, const Dual<GpuFloat>* f,
                       Where where) {
    for (std::size_t k = 0; k < exact.size(); ++k) {
        if (finite(f[k]) || !finite(exact[k])) continue;
        throw FloatEvaluationError(
            fmt::format("the GPU's float arithmetic overflows here {}: the value and its derivatives are {:.3g}, "
                        "{:.3g}, {:.3g} in double, and float holds magnitudes up to {:.3g}",
                        where(), exact[k].v, exact[k].du, exact[k].dv, kFloatMax),
            program.nodes[k].column, program.origins[k]);
    }
}

}  // namespace

void check_float_constants(const Expr& expr) {
    const Expr* one[] = {&expr};
    const Program program = compile_program(one);
    for (const Node& n : program.nodes) {
        if (n.op != Op::Constant) continue;
        const double m = std::abs(n.value);
        if (m > kFloatMax)
            throw ExprError(fmt::format("{:g} is beyond float's range (magnitudes up to {:.3g}): the GPU computes in float, "
                                        "where it would be infinite",
                                        n.value, kFloatMax),
                            n.column);
        if (m != 0.0 && m < kFloatMinNormal)
            throw ExprError(fmt::format("{:g} is below float's range (nonzero magnitudes from {:.3g}): the GPU computes in "
                                        "float, where it would be 0",
                                        n.value, kFloatMinNormal),
                            n.column);
    }
}

double check_float_evaluation(const Program& program, const ParametricSurface& s, int grid) {
    const int count = static_cast<int>(program.nodes.size());
    std::vector<Dual<double>> exact(program.nodes.size());
    glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
    struct Worst {
        double distance = 0.0, u = 0.0, v = 0.0;
        std::array<double, 3> gpu{}, reference{};
    } worst;
    for (int i = 0; i <= grid; ++i) {
        for (int j = 0; j <= grid; ++j) {
            // The GPU is handed (u, v) in float: both evaluate at that point, so that rounding the
            // parameters (at the edge of where the surface is defined) is not counted against it.
            const double u = static_cast<float>(i == grid ? s.u1 : s.u0 + (s.u1 - s.u0) * i / grid);
            const double v = static_cast<float>(j == grid ? s.v1 : s.v0 + (s.v1 - s.v0) * j / grid);
            const Dual<double>* d = evaluate_all_nodes(program, Dual<double>::variable_u(u), Dual<double>::variable_v(v));
            exact.assign(d, d + count);
            bool defined = true;
            for (int o : program.outputs) defined = defined && finite(exact[o]);
            if (!defined) continue;  // not a point of the surface: nothing for the GPU to match
            const Dual<GpuFloat>* f = evaluate_all_nodes(program, Dual<GpuFloat>::variable_u(GpuFloat(u)),
                                                         Dual<GpuFloat>::variable_v(GpuFloat(v)));
            check_no_overflow(program, exact, f, [&] { return at_point(u, v); });
            double distance2 = 0.0;
            for (int k = 0; k < 3; ++k) {
                const double e = exact[program.outputs[k]].v, g = f[program.outputs[k]].v.x;
                distance2 += (g - e) * (g - e);
                lo[k] = std::min(lo[k], e);
                hi[k] = std::max(hi[k], e);
            }
            const double distance = std::sqrt(distance2);
            if (distance > worst.distance) {
                worst = {distance, u, v, {}, {}};
                for (int k = 0; k < 3; ++k) {
                    worst.gpu[k] = f[program.outputs[k]].v.x;
                    worst.reference[k] = exact[program.outputs[k]].v;
                }
            }
        }
    }
    const double size = glm::length(hi - lo);
    if (worst.distance > kTolerance * size) {
        int axis = 0;  // the coordinate the furthest off
        for (int k = 1; k < 3; ++k)
            if (std::abs(worst.gpu[k] - worst.reference[k]) > std::abs(worst.gpu[axis] - worst.reference[axis])) axis = k;
        throw FloatEvaluationError(
            fmt::format("the GPU's float arithmetic computes {:.7g} {}, where the exact value is {:.7g}: {:.3g} apart, more "
                        "than {:g} of the surface's size ({:.3g}), so the GPU would draw another surface (large terms "
                        "that cancel?)",
                        worst.gpu[axis], at_point(worst.u, worst.v), worst.reference[axis],
                        std::abs(worst.gpu[axis] - worst.reference[axis]), kTolerance, size),
            0, axis);
    }
    return worst.distance;
}

double check_float_evaluation(const ImplicitSurface& s, int grid) {
    const Program& program = s.program;
    const int count = static_cast<int>(program.nodes.size());
    const int out = program.outputs.at(0);
    std::vector<Dual<double>> exact(program.nodes.size());
    double f_lo = HUGE_VAL, f_hi = -HUGE_VAL, worst = 0.0;
    dvec3 worst_at(0.0);
    double worst_gpu = 0.0, worst_reference = 0.0;
    for (int i = 0; i <= grid; ++i)
        for (int j = 0; j <= grid; ++j)
            for (int k = 0; k <= grid; ++k) {
                // The GPU is handed its points in float: both evaluate at the same point.
                dvec3 p;
                const int ijk[] = {i, j, k};
                for (int a = 0; a < 3; ++a)
                    p[a] = static_cast<float>(s.box_lo[a] + (s.box_hi[a] - s.box_lo[a]) * ijk[a] / grid);
                // Dual carries two partials: d/dx and d/dy in one pass, d/dz in the other.
                for (int pass = 0; pass < 2; ++pass) {
                    using D = Dual<double>;
                    using F = Dual<GpuFloat>;
                    const D xd[] = {pass ? D::constant(p.x) : D::variable_u(p.x),
                                    pass ? D::constant(p.y) : D::variable_v(p.y),
                                    pass ? D::variable_u(p.z) : D::constant(p.z)};
                    const F xf[] = {pass ? F::constant(p.x) : F::variable_u(GpuFloat(p.x)),
                                    pass ? F::constant(p.y) : F::variable_v(GpuFloat(p.y)),
                                    pass ? F::variable_u(GpuFloat(p.z)) : F::constant(p.z)};
                    const D* d = evaluate_all_nodes<D>(program, xd);
                    exact.assign(d, d + count);
                    if (!finite(exact[out])) break;  // f undefined here: no surface for the GPU to match
                    const F* f = evaluate_all_nodes<F>(program, xf);
                    check_no_overflow(program, exact, f, [&] {
                        return fmt::format("at (x, y, z) = ({:.6g}, {:.6g}, {:.6g})", p.x, p.y, p.z);
                    });
                    if (pass) continue;
                    f_lo = std::min(f_lo, exact[out].v);
                    f_hi = std::max(f_hi, exact[out].v);
                    const double difference = std::abs(static_cast<double>(f[out].v.x) - exact[out].v);
                    if (difference > worst) {
                        worst = difference;
                        worst_at = p;
                        worst_gpu = f[out].v.x;
                        worst_reference = exact[out].v;
                    }
                }
            }
    const double range = f_hi - f_lo;
    if (worst > kTolerance * range)
        throw FloatEvaluationError(
            fmt::format("the GPU's float arithmetic computes f = {:.7g} at (x, y, z) = ({:.6g}, {:.6g}, {:.6g}), where the "
                        "exact value is {:.7g}: {:.3g} apart, more than {:g} of f's range over the box ({:.3g}), so the "
                        "GPU would draw another surface (large terms that cancel?)",
                        worst_gpu, worst_at.x, worst_at.y, worst_at.z, worst_reference, worst, kTolerance, range),
            0, 0);
    return worst;
}

}  // namespace lancer::surface

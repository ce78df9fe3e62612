#pragma once
// Several expressions (a surface's x, y and z) compiled into one node list for fast repeated
// evaluation and for code generation: shared subexpressions are computed once (cos(v) in all
// three coordinates of a torus), constant subexpressions are folded in double, and nodes no
// output needs are dropped. Folding uses the same double operations as evaluate(), so a program
// computes bit for bit what evaluating each expression computes.
#include <span>
#include <vector>

#include "surface/dual.hpp"
#include "surface/expr/expr.hpp"
#include "surface/interval.hpp"

namespace lancer::surface {

struct Program {
    std::vector<Node> nodes;  // post-order; columns are those of the first occurrence
    std::vector<int> origins;  // per node: the expression (index into outputs) of that first occurrence
    std::vector<int> outputs;  // the node of each compiled expression, in order
};

Program compile_program(std::span<const Expr* const> expressions);

// The operations a program performs per evaluation (its nodes less constants and variables):
// the measure of its cost on the GPU, where each becomes a few lines of the tracer that the
// driver compiles, and that run at every Newton step of every ray.
int count_operations(const Program& program);

// Evaluates every output: out[i] is the value of expressions[i]. The first form is for
// expressions in u and v; the second takes the values of any number of variables.
template <class T>
void evaluate_program(const Program& program, const T& u, const T& v, T* out);
template <class T>
void evaluate_program(const Program& program, std::span<const T> variables, T* out);

extern template void evaluate_program(const Program&, const double&, const double&, double*);
extern template void evaluate_program(const Program&, const Interval&, const Interval&, Interval*);
extern template void evaluate_program(const Program&, const Dual<double>&, const Dual<double>&, Dual<double>*);
extern template void evaluate_program(const Program&, const Dual<Interval>&, const Dual<Interval>&, Dual<Interval>*);
extern template void evaluate_program(const Program&, const Dual<Dual<Interval>>&, const Dual<Dual<Interval>>&,
                                      Dual<Dual<Interval>>*);
extern template void evaluate_program(const Program&, std::span<const double>, double*);
extern template void evaluate_program(const Program&, std::span<const Interval>, Interval*);
extern template void evaluate_program(const Program&, std::span<const Dual<double>>, Dual<double>*);
extern template void evaluate_program(const Program&, std::span<const Dual<Interval>>, Dual<Interval>*);
struct GpuFloat;
extern template void evaluate_program(const Program&, const Dual<GpuFloat>&, const Dual<GpuFloat>&, Dual<GpuFloat>*);

// Every node's value, not only the outputs': values[i] for node i (a scratch buffer of this
// thread, valid until the next evaluation of this type).
template <class T>
const T* evaluate_all_nodes(const Program& program, const T& u, const T& v);
template <class T>
const T* evaluate_all_nodes(const Program& program, std::span<const T> variables);

// Dual<Interval> evaluation over a box that also reports whether every operation is proved
// defined, continuous and differentiable on the whole box: the condition under which the
// mean-value form and Krawczyk's test are valid. (Where it is not, the box may straddle the edge
// of an operation's domain or atan2's branch cut, and derivative bounds say nothing across it.)
bool evaluate_program_on_box(const Program& program, const Interval& u, const Interval& v, Dual<Interval>* out);
// The same for any number of variables, given as Dual<Interval>s (each with the derivatives the
// caller wants carried: the box's own directions, or a ray's).
bool evaluate_program_on_box(const Program& program, std::span<const Dual<Interval>> variables, Dual<Interval>* out);

}  // namespace lancer::surface

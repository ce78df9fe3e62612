#include "surface/expr/evaluate.hpp"

#include "surface/expr/evaluate_nodes.hpp"
#include "surface/expr/scratch.hpp"

namespace lancer::surface {

template <class T>
T evaluate(const Expr& expr, std::span<const T> variables) {
    const int count = static_cast<int>(expr.nodes.size());
    if (count == 0) return Lift<T>::constant(0.0);
    T* values = scratch_values<T>(expr.nodes.size());
    evaluate_nodes(expr.nodes.data(), count, variables.data(), values);
    return values[count - 1];
}

template <class T>
T evaluate(const Expr& expr, const T& u, const T& v) {
    const T uv[] = {u, v};
    return evaluate<T>(expr, std::span<const T>(uv));
}

template double evaluate(const Expr&, const double&, const double&);
template Interval evaluate(const Expr&, const Interval&, const Interval&);
template Dual<double> evaluate(const Expr&, const Dual<double>&, const Dual<double>&);
template Dual<Interval> evaluate(const Expr&, const Dual<Interval>&, const Dual<Interval>&);
template double evaluate(const Expr&, std::span<const double>);
template Interval evaluate(const Expr&, std::span<const Interval>);
template Dual<double> evaluate(const Expr&, std::span<const Dual<double>>);
template Dual<Interval> evaluate(const Expr&, std::span<const Dual<Interval>>);

}  // namespace lancer::surface

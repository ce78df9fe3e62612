#pragma once
// Evaluation of a parsed expression at a point (double), over a box (Interval), and with its
// partial derivatives (Dual<double>, Dual<Interval>; pass u as Dual<T>::variable_u(u) and v as
// Dual<T>::variable_v(v)). Values outside an operation's domain are NaN in double and make the
// interval empty (see interval.hpp).
#include <span>

#include "surface/dual.hpp"
#include "surface/expr/expr.hpp"
#include "surface/interval.hpp"

namespace lancer::surface {

// An expression in u and v.
template <class T>
T evaluate(const Expr& expr, const T& u, const T& v);
// An expression in any number of variables: variables[i] is the value of variable i.
template <class T>
T evaluate(const Expr& expr, std::span<const T> variables);

extern template double evaluate(const Expr&, const double&, const double&);
extern template Interval evaluate(const Expr&, const Interval&, const Interval&);
extern template Dual<double> evaluate(const Expr&, const Dual<double>&, const Dual<double>&);
extern template Dual<Interval> evaluate(const Expr&, const Dual<Interval>&, const Dual<Interval>&);
extern template double evaluate(const Expr&, std::span<const double>);
extern template Interval evaluate(const Expr&, std::span<const Interval>);
extern template Dual<double> evaluate(const Expr&, std::span<const Dual<double>>);
extern template Dual<Interval> evaluate(const Expr&, std::span<const Dual<Interval>>);

}  // namespace lancer::surface

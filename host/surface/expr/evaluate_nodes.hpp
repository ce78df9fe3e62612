#pragma once
// The evaluation kernel shared by evaluate(), compiled programs and the domain check: one
// switch over the operation, generic in the number type (double, Interval, Dual<double>,
// Dual<Interval>). The semantics of every operation live here and in the types' functions.
#include <cassert>

#include "surface/dual.hpp"
#include "surface/expr/expr.hpp"

namespace lancer::surface {

template <class T>
struct Lift {
    static T constant(double c) { return T(c); }
};
template <class T>
struct Lift<Dual<T>> {
    static Dual<T> constant(double c) { return Dual<T>::constant(c); }
};

// The value of node n, given the values of all earlier nodes and of the variables.
template <class T>
T apply_node(const Node& n, const T* values, const T* variables) {
    const T* a = n.a >= 0 ? &values[n.a] : nullptr;
    const T* b = n.b >= 0 ? &values[n.b] : nullptr;
    switch (n.op) {
        case Op::Constant: return Lift<T>::constant(n.value);
        case Op::Variable: return variables[static_cast<int>(n.value)];
        case Op::Add: return *a + *b;
        case Op::Sub: return *a - *b;
        case Op::Mul: return *a * *b;
        case Op::Div: return *a / *b;
        case Op::Neg: return -*a;
        case Op::PowInt: return powi(*a, static_cast<int>(n.value));
        case Op::PowConst: return powc(*a, n.value);
        case Op::Pow: return powr(*a, *b);
        case Op::Sqr: return sqr(*a);
        case Op::Sqrt: return sqrt(*a);
        case Op::Cbrt: return cbrt(*a);
        case Op::Exp: return exp(*a);
        case Op::Exp2: return exp2(*a);
        case Op::Log: return log(*a);
        case Op::Log2: return log2(*a);
        case Op::Log10: return log10(*a);
        case Op::Sin: return sin(*a);
        case Op::Cos: return cos(*a);
        case Op::Tan: return tan(*a);
        case Op::Asin: return asin(*a);
        case Op::Acos: return acos(*a);
        case Op::Atan: return atan(*a);
        case Op::Atan2: return atan2(*a, *b);
        case Op::Sinh: return sinh(*a);
        case Op::Cosh: return cosh(*a);
        case Op::Tanh: return tanh(*a);
        case Op::Asinh: return asinh(*a);
        case Op::Acosh: return acosh(*a);
        case Op::Atanh: return atanh(*a);
        case Op::Abs: return abs(*a);
        case Op::Min: return min(*a, *b);
        case Op::Max: return max(*a, *b);
        case Op::Hypot: return hypot(*a, *b);
    }
    assert(false && "unhandled Op");
    return Lift<T>::constant(0.0);
}

// Evaluates nodes[0..count) into values[0..count).
template <class T>
void evaluate_nodes(const Node* nodes, int count, const T* variables, T* values) {
    for (int i = 0; i < count; ++i) values[i] = apply_node(nodes[i], values, variables);
}

}  // namespace lancer::surface

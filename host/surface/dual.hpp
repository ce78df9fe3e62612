#pragma once
// Forward-mode differentiation: a value with its partial derivatives along u and v. With
// T = double it gives exact derivatives (to rounding); with T = Interval it bounds the value and
// the derivatives over a box of (u, v), which is what the mean-value form and Krawczyk need.
// Nested, Dual<Dual<Interval>> bounds the second partials too (d.du.du = S_uu, d.du.dv = S_uv,
// d.dv.dv = S_vv), for the GPU's Taylor bounds of S's partials over parts of a cell.
//
// The rules match the GLSL emitter's (expr/glsl_emitter.cpp) one for one, including the choices
// at kinks: d|x| = sign(x) dx (0 at 0), and min/max take the derivative of the argument they
// return (b on ties).
#include "surface/interval.hpp"
#include "surface/scalar_ops.hpp"

namespace lancer::surface {

template <class T>
struct Dual {
    T v{};
    T du{};
    T dv{};

    constexpr Dual() = default;
    constexpr Dual(const T& value, const T& d_u, const T& d_v) : v(value), du(d_u), dv(d_v) {}
    // A constant, as T(c) is for the scalar types, so that a Dual can be the T of a Dual.
    constexpr Dual(double c) : v(c), du(0.0), dv(0.0) {}

    static Dual constant(double c) { return {T(c), T(0.0), T(0.0)}; }
    static Dual variable_u(const T& u) { return {u, T(1.0), T(0.0)}; }
    static Dual variable_v(const T& v) { return {v, T(0.0), T(1.0)}; }
};

// Scales both derivatives by the chain-rule factor k = f'(x.v).
template <class T>
Dual<T> chain(const T& value, const T& k, const Dual<T>& x) {
    return {value, k * x.du, k * x.dv};
}

template <class T>
Dual<T> operator+(const Dual<T>& a, const Dual<T>& b) {
    return {a.v + b.v, a.du + b.du, a.dv + b.dv};
}
template <class T>
Dual<T> operator-(const Dual<T>& a, const Dual<T>& b) {
    return {a.v - b.v, a.du - b.du, a.dv - b.dv};
}
template <class T>
Dual<T> operator-(const Dual<T>& a) {
    return {-a.v, -a.du, -a.dv};
}
template <class T>
Dual<T> operator*(const Dual<T>& a, const Dual<T>& b) {
    return {a.v * b.v, a.du * b.v + a.v * b.du, a.dv * b.v + a.v * b.dv};
}
template <class T>
Dual<T> operator/(const Dual<T>& a, const Dual<T>& b) {
    T q = a.v / b.v;
    return {q, (a.du - q * b.du) / b.v, (a.dv - q * b.dv) / b.v};
}
template <class T>
Dual<T> operator*(double c, const Dual<T>& a) {
    return {T(c) * a.v, T(c) * a.du, T(c) * a.dv};
}

template <class T>
Dual<T> sqr(const Dual<T>& x) {
    return chain(sqr(x.v), T(2.0) * x.v, x);
}
template <class T>
Dual<T> powi(const Dual<T>& x, int n) {
    if (n == 0) return Dual<T>::constant(1.0);
    return chain(powi(x.v, n), T(static_cast<double>(n)) * powi(x.v, n - 1), x);
}
template <class T>
Dual<T> powc(const Dual<T>& x, double c) {
    return chain(powc(x.v, c), T(c) * powc(x.v, c - 1.0), x);
}
// d(x^y) = x^y (y' log x + y x'/x).
template <class T>
Dual<T> powr(const Dual<T>& x, const Dual<T>& y) {
    T p = powr(x.v, y.v);
    T lx = log(x.v);
    T r = y.v / x.v;
    return {p, p * (y.du * lx + r * x.du), p * (y.dv * lx + r * x.dv)};
}
template <class T>
Dual<T> sqrt(const Dual<T>& x) {
    T s = sqrt(x.v);
    return chain(s, T(0.5) / s, x);
}
template <class T>
Dual<T> cbrt(const Dual<T>& x) {
    T c = cbrt(x.v);
    return chain(c, T(1.0) / (T(3.0) * sqr(c)), x);
}
template <class T>
Dual<T> exp(const Dual<T>& x) {
    T e = exp(x.v);
    return chain(e, e, x);
}
template <class T>
Dual<T> exp2(const Dual<T>& x) {
    T e = exp2(x.v);
    return chain(e, e * T(0.69314718055994530942), x);
}
template <class T>
Dual<T> log(const Dual<T>& x) {
    return chain(log(x.v), T(1.0) / x.v, x);
}
template <class T>
Dual<T> log2(const Dual<T>& x) {
    return chain(log2(x.v), T(1.0) / (x.v * T(0.69314718055994530942)), x);
}
template <class T>
Dual<T> log10(const Dual<T>& x) {
    return chain(log10(x.v), T(1.0) / (x.v * T(2.30258509299404568402)), x);
}
template <class T>
Dual<T> sin(const Dual<T>& x) {
    return chain(sin(x.v), cos(x.v), x);
}
template <class T>
Dual<T> cos(const Dual<T>& x) {
    return chain(cos(x.v), -sin(x.v), x);
}
template <class T>
Dual<T> tan(const Dual<T>& x) {
    T t = tan(x.v);
    return chain(t, T(1.0) + sqr(t), x);
}
template <class T>
Dual<T> asin(const Dual<T>& x) {
    return chain(asin(x.v), T(1.0) / sqrt(T(1.0) - sqr(x.v)), x);
}
template <class T>
Dual<T> acos(const Dual<T>& x) {
    return chain(acos(x.v), T(-1.0) / sqrt(T(1.0) - sqr(x.v)), x);
}
template <class T>
Dual<T> atan(const Dual<T>& x) {
    return chain(atan(x.v), T(1.0) / (T(1.0) + sqr(x.v)), x);
}
// d atan2(y, x) = (x dy - y dx) / (x^2 + y^2).
template <class T>
Dual<T> atan2(const Dual<T>& y, const Dual<T>& x) {
    T r2 = sqr(x.v) + sqr(y.v);
    return {atan2(y.v, x.v), (x.v * y.du - y.v * x.du) / r2, (x.v * y.dv - y.v * x.dv) / r2};
}
template <class T>
Dual<T> sinh(const Dual<T>& x) {
    return chain(sinh(x.v), cosh(x.v), x);
}
template <class T>
Dual<T> cosh(const Dual<T>& x) {
    return chain(cosh(x.v), sinh(x.v), x);
}
template <class T>
Dual<T> tanh(const Dual<T>& x) {
    T t = tanh(x.v);
    return chain(t, T(1.0) - sqr(t), x);
}
template <class T>
Dual<T> asinh(const Dual<T>& x) {
    return chain(asinh(x.v), T(1.0) / sqrt(sqr(x.v) + T(1.0)), x);
}
template <class T>
Dual<T> acosh(const Dual<T>& x) {
    return chain(acosh(x.v), T(1.0) / sqrt(sqr(x.v) - T(1.0)), x);
}
template <class T>
Dual<T> atanh(const Dual<T>& x) {
    return chain(atanh(x.v), T(1.0) / (T(1.0) - sqr(x.v)), x);
}
template <class T>
Dual<T> hypot(const Dual<T>& a, const Dual<T>& b) {
    T h = hypot(a.v, b.v);
    return {h, (a.v * a.du + b.v * b.du) / h, (a.v * a.dv + b.v * b.dv) / h};
}

// The kinks: double takes the branch, Interval takes the hull of the branches it cannot decide.
inline Dual<double> abs(const Dual<double>& x) {
    double s = x.v > 0.0 ? 1.0 : (x.v < 0.0 ? -1.0 : 0.0);
    return chain(std::abs(x.v), s, x);
}
inline Dual<double> min(const Dual<double>& a, const Dual<double>& b) { return a.v < b.v ? a : b; }
inline Dual<double> max(const Dual<double>& a, const Dual<double>& b) { return a.v > b.v ? a : b; }

inline Dual<Interval> abs(const Dual<Interval>& x) {
    if (x.v.lo > 0.0) return x;
    if (x.v.hi < 0.0) return -x;
    Interval su{-x.du.mag(), x.du.mag()}, sv{-x.dv.mag(), x.dv.mag()};
    return {abs(x.v), su, sv};
}
inline Dual<Interval> min(const Dual<Interval>& a, const Dual<Interval>& b) {
    if (a.v.hi < b.v.lo) return a;
    if (b.v.hi <= a.v.lo) return b;
    return {min(a.v, b.v), hull(a.du, b.du), hull(a.dv, b.dv)};
}
inline Dual<Interval> max(const Dual<Interval>& a, const Dual<Interval>& b) {
    if (a.v.lo > b.v.hi) return a;
    if (b.v.lo >= a.v.hi) return b;
    return {max(a.v, b.v), hull(a.du, b.du), hull(a.dv, b.dv)};
}

// Second order: the kinks have no bounded second derivative where the interval cannot decide
// the branch.
inline Dual<Dual<Interval>> abs(const Dual<Dual<Interval>>& x) {
    if (x.v.v.lo > 0.0) return x;
    if (x.v.v.hi < 0.0) return -x;
    const Interval all{-kInf, kInf};
    return {abs(x.v), {Interval{-x.du.v.mag(), x.du.v.mag()}, all, all}, {Interval{-x.dv.v.mag(), x.dv.v.mag()}, all, all}};
}
inline Dual<Dual<Interval>> min(const Dual<Dual<Interval>>& a, const Dual<Dual<Interval>>& b) {
    if (a.v.v.hi < b.v.v.lo) return a;
    if (b.v.v.hi <= a.v.v.lo) return b;
    const Interval all{-kInf, kInf};
    return {min(a.v, b.v), {hull(a.du.v, b.du.v), all, all}, {hull(a.dv.v, b.dv.v), all, all}};
}
inline Dual<Dual<Interval>> max(const Dual<Dual<Interval>>& a, const Dual<Dual<Interval>>& b) {
    if (a.v.v.lo > b.v.v.hi) return a;
    if (b.v.v.lo >= a.v.v.hi) return b;
    const Interval all{-kInf, kInf};
    return {max(a.v, b.v), {hull(a.du.v, b.du.v), all, all}, {hull(a.dv.v, b.dv.v), all, all}};
}

}  // namespace lancer::surface

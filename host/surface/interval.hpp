#pragma once
// Interval arithmetic with outward rounding: every operation returns an interval that contains
// the exact result for every choice of operands in its inputs, and also the value the same
// operation computes in double (so sampled values of an expression always lie in its interval).
//
// Conventions:
//  * The empty interval (lo > hi) means "undefined everywhere here", e.g. sqrt([-2, -1]). It
//    propagates through every operation. Partly invalid inputs are clipped to the domain:
//    sqrt([-1, 4]) = [0, 2].
//  * Division by an interval that contains 0 gives the whole real line [-inf, inf].
//  * A lower bound is never +inf and an upper bound never -inf (rounding outward turns an
//    overflow into the largest finite double on the inner side), so inf - inf never occurs.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace lancer::surface {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// The neighbours of x towards -inf and +inf (x itself for NaN and for the infinity in that
// direction). Bit arithmetic, because std::nextafter is a library call and intervals are hot.
inline double next_down(double x) {
    if (!(x > -kInf)) return x;  // -inf or NaN
    if (x == 0.0) return -std::numeric_limits<double>::denorm_min();
    auto bits = std::bit_cast<std::uint64_t>(x);
    return std::bit_cast<double>(x > 0.0 ? bits - 1 : bits + 1);
}
inline double next_up(double x) { return -next_down(-x); }
inline double down(double x, int ulps) {
    for (int i = 0; i < ulps; ++i) x = next_down(x);
    return x;
}
inline double up(double x, int ulps) {
    for (int i = 0; i < ulps; ++i) x = next_up(x);
    return x;
}

struct Interval {
    double lo = 0.0;
    double hi = 0.0;

    constexpr Interval() = default;
    constexpr Interval(double x) : lo(x), hi(x) {}  // NOLINT: a number is a point interval
    constexpr Interval(double l, double h) : lo(l), hi(h) {}

    static constexpr Interval empty() { return {kInf, -kInf}; }
    static constexpr Interval entire() { return {-kInf, kInf}; }

    bool is_empty() const { return !(lo <= hi); }
    bool contains(double x) const { return lo <= x && x <= hi; }
    bool contains_zero() const { return lo <= 0.0 && 0.0 <= hi; }
    bool is_finite() const { return std::isfinite(lo) && std::isfinite(hi); }
    double width() const { return hi - lo; }
    double mid() const;
    // The largest and the smallest |x| over the interval.
    double mag() const { return std::max(std::abs(lo), std::abs(hi)); }
    double mig() const { return contains_zero() ? 0.0 : std::min(std::abs(lo), std::abs(hi)); }
};

// A point inside the interval (finite even when a bound is infinite).
inline double Interval::mid() const {
    if (lo == -kInf && hi == kInf) return 0.0;
    if (lo == -kInf) return hi - (1.0 + std::abs(hi));
    if (hi == kInf) return lo + (1.0 + std::abs(lo));
    double m = 0.5 * (lo + hi);
    if (!std::isfinite(m)) m = 0.5 * lo + 0.5 * hi;
    return std::clamp(m, lo, hi);
}

inline bool operator==(const Interval& a, const Interval& b) { return a.lo == b.lo && a.hi == b.hi; }

// The smallest interval containing both (the empty interval is the identity).
inline Interval hull(const Interval& a, const Interval& b) {
    if (a.is_empty()) return b;
    if (b.is_empty()) return a;
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
}
inline Interval intersect(const Interval& a, const Interval& b) {
    Interval r{std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
    return r.is_empty() ? Interval::empty() : r;
}

inline Interval operator+(const Interval& a, const Interval& b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    return {next_down(a.lo + b.lo), next_up(a.hi + b.hi)};
}
inline Interval operator-(const Interval& a, const Interval& b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    return {next_down(a.lo - b.hi), next_up(a.hi - b.lo)};
}
inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }

namespace interval_detail {
// x * y with 0 * inf = 0: an infinite bound stands for "arbitrarily large", and 0 times any
// finite number is 0.
inline double times(double x, double y) {
    double p = x * y;
    return p == p ? p : 0.0;
}
}  // namespace interval_detail

inline Interval operator*(const Interval& a, const Interval& b) {
    using interval_detail::times;
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    double p1 = times(a.lo, b.lo), p2 = times(a.lo, b.hi), p3 = times(a.hi, b.lo), p4 = times(a.hi, b.hi);
    return {next_down(std::min(std::min(p1, p2), std::min(p3, p4))),
            next_up(std::max(std::max(p1, p2), std::max(p3, p4)))};
}

Interval operator/(const Interval& a, const Interval& b);

inline Interval& operator+=(Interval& a, const Interval& b) { return a = a + b; }
inline Interval& operator-=(Interval& a, const Interval& b) { return a = a - b; }
inline Interval& operator*=(Interval& a, const Interval& b) { return a = a * b; }
inline Interval& operator/=(Interval& a, const Interval& b) { return a = a / b; }

// x^n for an integer n (negative bases allowed), x^c for a real constant c (x >= 0), and
// x^y = exp(y log x) (x > 0; 0^y = 0 for y > 0).
Interval powi(const Interval& x, int n);
Interval powc(const Interval& x, double c);
Interval powr(const Interval& x, const Interval& y);
Interval sqr(const Interval& x);
Interval sqrt(const Interval& x);
Interval cbrt(const Interval& x);
Interval exp(const Interval& x);
Interval exp2(const Interval& x);
Interval log(const Interval& x);
Interval log2(const Interval& x);
Interval log10(const Interval& x);
Interval sin(const Interval& x);
Interval cos(const Interval& x);
Interval tan(const Interval& x);
Interval asin(const Interval& x);
Interval acos(const Interval& x);
Interval atan(const Interval& x);
Interval atan2(const Interval& y, const Interval& x);
Interval sinh(const Interval& x);
Interval cosh(const Interval& x);
Interval tanh(const Interval& x);
Interval asinh(const Interval& x);
Interval acosh(const Interval& x);
Interval atanh(const Interval& x);
Interval abs(const Interval& x);
Interval min(const Interval& a, const Interval& b);
Interval max(const Interval& a, const Interval& b);
Interval hypot(const Interval& a, const Interval& b);

}  // namespace lancer::surface

// Outward-rounded interval functions. Bounds of library functions (sin, exp, pow, ...) are
// widened by kLibmUlps: glibc documents errors of at most 1-2 ulp for these, so the interval
// contains both the exact range and the values the same functions return in double.
#include "surface/interval.hpp"

#include "core/constants.hpp"

namespace lancer::surface {
namespace {

constexpr int kLibmUlps = 4;

double lib_down(double x) { return down(x, kLibmUlps); }
double lib_up(double x) { return up(x, kLibmUlps); }

// The interval of a nondecreasing library function f, or of a nonincreasing one.
template <class F>
Interval increasing(const Interval& x, F f) {
    return {lib_down(f(x.lo)), lib_up(f(x.hi))};
}
template <class F>
Interval decreasing(const Interval& x, F f) {
    return {lib_down(f(x.hi)), lib_up(f(x.lo))};
}

Interval clamp_to(Interval r, double lo, double hi) {
    return {std::clamp(r.lo, lo, hi), std::clamp(r.hi, lo, hi)};
}

// Whether [lo, hi] may contain offset + k * period for some integer k. "May": the test widens
// the interval by far more than the rounding error of the arithmetic below (and of pi itself),
// so a true extremum or pole is never missed; a false "yes" only loosens the result.
bool may_contain_periodic(const Interval& x, double offset, double period) {
    double margin = 1e-14 * (1.0 + x.mag());
    double lo = x.lo - margin, hi = x.hi + margin;
    double k = std::ceil((lo - offset) / period);
    return offset + k * period <= hi;
}

// True when the argument is so wide or so large that a periodic function takes every value.
bool covers_a_period(const Interval& x) {
    return !x.is_finite() || x.width() >= 2.0 * kPi || x.mag() > 1e15;
}

}  // namespace

Interval operator/(const Interval& a, const Interval& b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    if (b.contains_zero()) return Interval::entire();
    double q1 = a.lo / b.lo, q2 = a.lo / b.hi, q3 = a.hi / b.lo, q4 = a.hi / b.hi;
    if (q1 != q1 || q2 != q2 || q3 != q3 || q4 != q4) return Interval::entire();  // inf / inf
    return {next_down(std::min(std::min(q1, q2), std::min(q3, q4))),
            next_up(std::max(std::max(q1, q2), std::max(q3, q4)))};
}

Interval sqr(const Interval& x) {
    if (x.is_empty()) return x;
    double m = x.mig(), M = x.mag();
    return {std::max(0.0, next_down(m * m)), next_up(M * M)};
}

Interval powi(const Interval& x, int n) {
    if (x.is_empty()) return x;
    if (n == 0) return Interval(1.0);
    if (n < 0) return Interval(1.0) / powi(x, -n);
    if (n == 1) return x;
    if (n == 2) return sqr(x);
    if (n % 2 == 0) {
        return {std::max(0.0, lib_down(std::pow(x.mig(), n))), lib_up(std::pow(x.mag(), n))};
    }
    return {lib_down(std::pow(x.lo, n)), lib_up(std::pow(x.hi, n))};
}

Interval powc(const Interval& x, double c) {
    if (x.is_empty() || x.hi < 0.0) return Interval::empty();
    Interval d{std::max(x.lo, 0.0), x.hi};
    if (c == 0.0) return Interval(1.0);
    Interval r = c > 0.0 ? increasing(d, [c](double t) { return std::pow(t, c); })
                         : decreasing(d, [c](double t) { return std::pow(t, c); });
    r.lo = std::max(r.lo, 0.0);
    return r;
}

// x^y for x > 0 is monotone in x for each fixed y and monotone in y for each fixed x, so its
// extremes over a box lie at the box's corners (with the limits 0^y at x = 0).
Interval powr(const Interval& x, const Interval& y) {
    if (x.is_empty() || y.is_empty() || x.hi < 0.0) return Interval::empty();
    if (x.hi == 0.0) return y.hi > 0.0 ? Interval(0.0) : Interval::empty();
    double xs[2] = {std::max(x.lo, 0.0), x.hi};
    double ys[2] = {y.lo, y.hi};
    double lo = kInf, hi = -kInf;
    for (double a : xs) {
        for (double b : ys) {
            double p = std::pow(a, b);
            if (p != p) return Interval::entire();
            lo = std::min(lo, p);
            hi = std::max(hi, p);
        }
    }
    return {std::max(0.0, lib_down(lo)), lib_up(hi)};
}

Interval sqrt(const Interval& x) {
    if (x.is_empty() || x.hi < 0.0) return Interval::empty();
    double lo = x.lo > 0.0 ? std::max(0.0, next_down(std::sqrt(x.lo))) : 0.0;
    return {lo, next_up(std::sqrt(x.hi))};
}

Interval cbrt(const Interval& x) {
    if (x.is_empty()) return x;
    return increasing(x, [](double t) { return std::cbrt(t); });
}

Interval exp(const Interval& x) {
    if (x.is_empty()) return x;
    Interval r = increasing(x, [](double t) { return std::exp(t); });
    r.lo = std::max(r.lo, 0.0);
    return r;
}

Interval exp2(const Interval& x) {
    if (x.is_empty()) return x;
    Interval r = increasing(x, [](double t) { return std::exp2(t); });
    r.lo = std::max(r.lo, 0.0);
    return r;
}

namespace {
template <class F>
Interval logarithm(const Interval& x, F f) {
    if (x.is_empty() || x.hi <= 0.0) return Interval::empty();
    return {x.lo > 0.0 ? lib_down(f(x.lo)) : -kInf, lib_up(f(x.hi))};
}
}  // namespace

Interval log(const Interval& x) { return logarithm(x, [](double t) { return std::log(t); }); }
Interval log2(const Interval& x) { return logarithm(x, [](double t) { return std::log2(t); }); }
Interval log10(const Interval& x) { return logarithm(x, [](double t) { return std::log10(t); }); }

Interval sin(const Interval& x) {
    if (x.is_empty()) return x;
    if (covers_a_period(x)) return {-1.0, 1.0};
    double a = std::sin(x.lo), b = std::sin(x.hi);
    Interval r{lib_down(std::min(a, b)), lib_up(std::max(a, b))};
    if (may_contain_periodic(x, 0.5 * kPi, 2.0 * kPi)) r.hi = 1.0;
    if (may_contain_periodic(x, -0.5 * kPi, 2.0 * kPi)) r.lo = -1.0;
    return clamp_to(r, -1.0, 1.0);
}

Interval cos(const Interval& x) {
    if (x.is_empty()) return x;
    if (covers_a_period(x)) return {-1.0, 1.0};
    double a = std::cos(x.lo), b = std::cos(x.hi);
    Interval r{lib_down(std::min(a, b)), lib_up(std::max(a, b))};
    if (may_contain_periodic(x, 0.0, 2.0 * kPi)) r.hi = 1.0;
    if (may_contain_periodic(x, kPi, 2.0 * kPi)) r.lo = -1.0;
    return clamp_to(r, -1.0, 1.0);
}

Interval tan(const Interval& x) {
    if (x.is_empty()) return x;
    if (covers_a_period(x) || x.width() >= kPi || may_contain_periodic(x, 0.5 * kPi, kPi)) return Interval::entire();
    return increasing(x, [](double t) { return std::tan(t); });
}

Interval asin(const Interval& x) {
    if (x.is_empty() || x.lo > 1.0 || x.hi < -1.0) return Interval::empty();
    Interval d{std::max(x.lo, -1.0), std::min(x.hi, 1.0)};
    return increasing(d, [](double t) { return std::asin(t); });
}

Interval acos(const Interval& x) {
    if (x.is_empty() || x.lo > 1.0 || x.hi < -1.0) return Interval::empty();
    Interval d{std::max(x.lo, -1.0), std::min(x.hi, 1.0)};
    Interval r = decreasing(d, [](double t) { return std::acos(t); });
    r.lo = std::max(r.lo, 0.0);
    return r;
}

Interval atan(const Interval& x) {
    if (x.is_empty()) return x;
    return increasing(x, [](double t) { return std::atan(t); });
}

// The angle of the points of a box. Away from the origin and from the branch cut (the negative
// x axis, where atan2 jumps from pi to -pi) the extreme angles are at the box's corners.
Interval atan2(const Interval& y, const Interval& x) {
    if (y.is_empty() || x.is_empty()) return Interval::empty();
    const Interval all{-up(kPi, 1), up(kPi, 1)};
    if (y.contains_zero() && x.lo <= 0.0) return all;
    double lo = kInf, hi = -kInf;
    for (double b : {y.lo, y.hi}) {
        for (double a : {x.lo, x.hi}) {
            double angle = std::atan2(b, a);
            lo = std::min(lo, angle);
            hi = std::max(hi, angle);
        }
    }
    return clamp_to({lib_down(lo), lib_up(hi)}, all.lo, all.hi);
}

Interval sinh(const Interval& x) {
    if (x.is_empty()) return x;
    return increasing(x, [](double t) { return std::sinh(t); });
}

Interval cosh(const Interval& x) {
    if (x.is_empty()) return x;
    return {std::max(1.0, lib_down(std::cosh(x.mig()))), lib_up(std::cosh(x.mag()))};
}

Interval tanh(const Interval& x) {
    if (x.is_empty()) return x;
    return clamp_to(increasing(x, [](double t) { return std::tanh(t); }), -1.0, 1.0);
}

Interval asinh(const Interval& x) {
    if (x.is_empty()) return x;
    return increasing(x, [](double t) { return std::asinh(t); });
}

Interval acosh(const Interval& x) {
    if (x.is_empty() || x.hi < 1.0) return Interval::empty();
    Interval r = increasing({std::max(x.lo, 1.0), x.hi}, [](double t) { return std::acosh(t); });
    r.lo = std::max(r.lo, 0.0);
    return r;
}

Interval atanh(const Interval& x) {
    if (x.is_empty() || x.lo >= 1.0 || x.hi <= -1.0) return Interval::empty();
    return {x.lo <= -1.0 ? -kInf : lib_down(std::atanh(x.lo)), x.hi >= 1.0 ? kInf : lib_up(std::atanh(x.hi))};
}

Interval abs(const Interval& x) {
    if (x.is_empty()) return x;
    if (x.lo >= 0.0) return x;
    if (x.hi <= 0.0) return -x;
    return {0.0, x.mag()};
}

Interval min(const Interval& a, const Interval& b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
}

Interval max(const Interval& a, const Interval& b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
}

Interval hypot(const Interval& a, const Interval& b) {
    if (a.is_empty() || b.is_empty()) return Interval::empty();
    return {std::max(0.0, lib_down(std::hypot(a.mig(), b.mig()))), lib_up(std::hypot(a.mag(), b.mag()))};
}

}  // namespace lancer::surface

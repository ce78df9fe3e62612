#pragma once
// The double versions of the operations that expressions offer, with the same domains as their
// interval twins (interval.hpp) and as GLSL: powr(x, y) is undefined (NaN) for x < 0 even when y
// is an integer, powc(x, c) likewise, so that a sampled value and its interval always agree.
#include <cmath>

namespace lancer::surface {

// Brought into this namespace so that generic code (Dual<T>, the evaluator) finds the double
// overloads next to the Interval ones by ordinary lookup.
using std::abs, std::sqrt, std::cbrt, std::exp, std::exp2, std::log, std::log2, std::log10;
using std::sin, std::cos, std::tan, std::asin, std::acos, std::atan, std::atan2;
using std::sinh, std::cosh, std::tanh, std::asinh, std::acosh, std::atanh, std::hypot;

inline double sqr(double x) { return x * x; }
inline double min(double a, double b) { return a < b ? a : b; }
inline double max(double a, double b) { return a > b ? a : b; }

inline double powi(double x, int n) {
    switch (n) {
        case 0: return 1.0;
        case 1: return x;
        case 2: return x * x;
        case -1: return 1.0 / x;
        case -2: return 1.0 / (x * x);
        default: return std::pow(x, n);
    }
}
inline double powc(double x, double c) { return x >= 0.0 ? std::pow(x, c) : std::nan(""); }
inline double powr(double x, double y) {
    if (x > 0.0) return std::pow(x, y);
    if (x == 0.0 && y > 0.0) return 0.0;
    return std::nan("");
}

}  // namespace lancer::surface

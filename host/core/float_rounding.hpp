#pragma once
// Doubles to floats rounded outward: a float bound that still holds its double original.
#include <cmath>
#include <limits>

namespace lancer {

// float(x) rounded toward -inf.
inline float round_down(double x) {
    const float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

// float(x) rounded toward +inf.
inline float round_up(double x) {
    const float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace lancer

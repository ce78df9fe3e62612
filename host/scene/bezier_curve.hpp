#pragma once
// A Bezier curve of degree n <= 3 over s in [0, 1], given by its control values (numbers, or
// points of the (r, y) plane): a lathe's segment (scene.hpp's LatheSegment), for the reader's
// checks (parse_lathe.cpp, lathe_crossing.cpp) and the CPU reference's search (cpu/shapes/lathe.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace lancer {

// The curve at s (de Casteljau).
template <class T>
T bezier_at(std::array<T, 4> w, int n, double s) {
    for (int level = n; level > 0; --level)
        for (int i = 0; i < level; ++i) w[i] = (1.0 - s) * w[i] + s * w[i + 1];
    return w[0];
}

// The curve's derivative at s.
inline double bezier_slope(const std::array<double, 4>& b, int n, double s) {
    std::array<double, 4> d{};
    for (int i = 0; i < n; ++i) d[i] = n * (b[i + 1] - b[i]);
    return bezier_at(d, n - 1, s);
}

// The curve's pieces over [0, s] (left) and over [s, 1] (right), each of degree n (de Casteljau).
template <class T>
void bezier_split(const std::array<T, 4>& c, int n, double s, std::array<T, 4>& left, std::array<T, 4>& right) {
    std::array<T, 4> w = c;
    left[0] = w[0];
    right[n] = w[n];
    for (int level = n; level > 0; --level) {
        for (int i = 0; i < level; ++i) w[i] = (1.0 - s) * w[i] + s * w[i + 1];
        left[n - level + 1] = w[0];
        right[level - 1] = w[level - 1];
    }
}

// Where the curve turns: the roots in (0, 1) of its derivative (a Bezier of degree n - 1 in the
// control values' differences: at most a quadratic, solved without cancellation), in order, each once.
inline std::vector<double> bezier_turning_points(const std::array<double, 4>& b, int n) {
    std::vector<double> roots;
    if (n < 2) return roots;
    std::array<double, 3> d{};
    for (int i = 0; i < n; ++i) d[i] = b[i + 1] - b[i];
    // The derivative over n in power form: c0 + c1 s + c2 s^2.
    const double c0 = d[0], c1 = n == 2 ? d[1] - d[0] : 2.0 * (d[1] - d[0]), c2 = n == 2 ? 0.0 : d[0] - 2.0 * d[1] + d[2];
    auto keep = [&](double s) {
        if (s > 0.0 && s < 1.0) roots.push_back(s);
    };
    if (c2 != 0.0) {
        const double disc = c1 * c1 - 4.0 * c2 * c0;
        if (disc < 0.0) return roots;
        const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
        if (q != 0.0) keep(c0 / q);
        keep(q / c2);
    } else if (c1 != 0.0) {
        keep(-c0 / c1);
    }
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    return roots;
}

}  // namespace lancer

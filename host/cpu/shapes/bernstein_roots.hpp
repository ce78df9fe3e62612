#pragma once
// Certified roots of a quartic g(tau) over tau in [-1, 1] by Bernstein subdivision, for the
// reference's torus (torus.cpp) and blob (blob.cpp), whose surfaces are a quartic in t along a
// ray (the torus's over its segment, the blob's over each stretch between its components' ends).
// split and isolate take Bernstein coefficients of any degree (the lathe's sextics, lathe.cpp,
// built in Bernstein form over their own interval).
// g's Bernstein coefficients over a piece enclose g there (convex hull), and their sign
// variations bound its roots there (Descartes' rule, which is exact for one variation):
//   * every coefficient beyond its rounding bound on one side: no root in the piece;
//   * one variation, every coefficient beyond its rounding bound: exactly one root, found by
//     bisection on g evaluated directly by the caller (accurate near the surface);
//   * else the piece is halved (de Casteljau), nearer half first, down to 1e-12 of [-1, 1],
//     where a piece whose coefficients still straddle 0 within their rounding is a touching point
//     (a ray tangent to the surface): a hit, as the implicit surfaces' reference counts it
//     (cpu/shapes/implicit.cpp).
// Nothing is missed: a piece is dropped only on a proof that g keeps one sign over it.
#include <algorithm>
#include <array>
#include <cmath>

namespace lancer::cpu::bernstein {

constexpr double kEpsilon = 2.220446049250313e-16;
constexpr double kTouchingWidth = 1e-12;  // of tau's [-1, 1]: a piece this narrow is a point

using Quartic = std::array<double, 5>;

struct Form {
    Quartic c;         // Bernstein coefficients over [-1, 1]
    double magnitude;  // the largest sum of the magnitudes of the terms a coefficient was formed from
};

// g = sum p[i] tau^i in Bernstein form over [-1, 1]; m[i] >= |p[i]|, the sum of the magnitudes of
// the terms p[i] was formed from, is carried alongside (the caller's rounding bound grows with it).
inline Form from_power(const Quartic& p, const Quartic& m) {
    // tau = 2x - 1 on x in [0, 1], then Bernstein coefficients over [0, 1] (implicit.cpp's
    // descartes_agrees does the same for any degree).
    Quartic px{}, mx{};
    for (int i = 0; i < 5; ++i) {
        double binomial = 1.0;  // C(i, j)
        for (int j = 0; j <= i; ++j) {
            const double term = p[i] * binomial * std::ldexp(((i - j) & 1) ? -1.0 : 1.0, j);
            px[j] += term;
            mx[j] += std::abs(m[i] * binomial * std::ldexp(1.0, j));
            binomial = binomial * double(i - j) / double(j + 1);
        }
    }
    Form form{};
    static constexpr double kBinomial4[5] = {1, 4, 6, 4, 1};
    for (int j = 0; j < 5; ++j) {
        double sum = 0.0, sum_mag = 0.0, c_jk = 1.0;  // C(j, k)
        for (int kk = 0; kk <= j; ++kk) {
            sum += c_jk / kBinomial4[kk] * px[kk];
            sum_mag += c_jk / kBinomial4[kk] * mx[kk];
            c_jk = c_jk * double(j - kk) / double(kk + 1);
        }
        form.c[j] = sum;
        form.magnitude = std::max(form.magnitude, sum_mag);
    }
    return form;
}

// The halves [0, 1/2] and [1/2, 1] of a piece (de Casteljau).
template <std::size_t N>
inline void split(const std::array<double, N>& c, std::array<double, N>& left, std::array<double, N>& right) {
    std::array<double, N> w = c;
    const std::size_t n = c.size() - 1;
    left[0] = w[0];
    right[n] = w[n];
    for (std::size_t k = 1; k <= n; ++k) {
        for (std::size_t i = 0; i + k <= n; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
        left[k] = w[0];
        right[n - k] = w[n - k];
    }
}

// The one root in (lo, hi) where g(lo) has sign `lo_positive`: bisection on value(tau) = g(tau)
// until the bracket stops shrinking.
template <class Value>
double bisect(const Value& value, double lo, double hi, bool lo_positive) {
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        const double v = value(mid);
        if (v == 0.0) return mid;
        if ((v > 0.0) == lo_positive) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

// The roots of g in the piece (lo, hi) of [-1, 1] whose Bernstein coefficients are c, each within
// `error` of g's, nearest (lowest tau) first: accept(tau, from, to) is called with each, and the
// piece it was told in (from = to = tau for a root proved simple), and returns true to stop the
// search (the nearest wanted, and found), which isolate then returns. With `flat_runs`, a piece
// whose coefficients all lie within rounding of 0 is one touching point (its middle), not halved
// into 1e-12 pieces that would each be one: g is 0 to rounding along it (about a tangent point,
// some 1e-6 of [-1, 1]; along a blob's capsule side, all of it).
template <class Value, class Accept, std::size_t N>
bool isolate(const std::array<double, N>& c, double lo, double hi, double error, const Value& value, const Accept& accept, bool flat_runs = false) {
    double min = c[0], max = c[0];
    for (double x : c) {
        min = std::min(min, x);
        max = std::max(max, x);
    }
    if (min > error || max < -error) return false;  // proved: no root here
    if (flat_runs && min >= -error && max <= error) return accept(0.5 * (lo + hi), lo, hi);
    bool certain = true;
    int variations = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
        certain = certain && std::abs(c[i]) > error;
        if (i > 0 && (c[i] > 0.0) != (c[i - 1] > 0.0)) ++variations;
    }
    if (certain && variations == 1) {
        const double root = bisect(value, lo, hi, c[0] > 0.0);
        return accept(root, root, root);
    }
    if (hi - lo <= kTouchingWidth) return accept(0.5 * (lo + hi), lo, hi);  // within rounding of a touching point
    std::array<double, N> left, right;
    split(c, left, right);
    const double mid = 0.5 * (lo + hi);
    // Each de Casteljau level averages: one more rounding of the largest coefficient.
    const double next = error + 2.0 * kEpsilon * std::max(std::abs(min), std::abs(max));
    if (isolate(left, lo, mid, next, value, accept, flat_runs)) return true;
    return isolate(right, mid, hi, next, value, accept, flat_runs);
}

}  // namespace lancer::cpu::bernstein

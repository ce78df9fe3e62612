#pragma once
// Exact rational Bezier surfaces of revolution (Piegl & Tiller): quarter circles as rational
// quadratic arcs, swept and degree-elevated to bicubic. The analytic twins of tests that
// compare lancer's patch and parametric surfaces with closed-form ones (sphere, torus).
#include <array>
#include <cmath>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "surface/bezier_patch.hpp"

namespace lancer::test {

using glm::dvec2;
using glm::dvec3;
using glm::dvec4;
using surface::BezierPatch;

inline const double kHalfSqrt2 = std::sqrt(0.5);

// A rational quadratic arc's control points and weights.
struct Arc {
    std::array<dvec2, 3> p;
    std::array<double, 3> w;
};

// The quarter of the circle (centre, radius) from angle k * 90 degrees to (k + 1) * 90 degrees.
inline Arc quarter_circle(dvec2 centre, double radius, int k) {
    const dvec2 dirs[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};  // exact, unlike cos/sin of k pi/2
    dvec2 a = dirs[k % 4], b = dirs[(k + 1) % 4];
    return {{centre + radius * a, centre + radius * (a + b), centre + radius * b}, {1.0, kHalfSqrt2, 1.0}};
}

// Degree elevation 2 -> 3 of one homogeneous curve: exact.
inline std::array<dvec4, 4> elevate(const std::array<dvec4, 3>& h) {
    return {h[0], (h[0] + 2.0 * h[1]) / 3.0, (2.0 * h[1] + h[2]) / 3.0, h[2]};
}

// The profile arc (rho, z) swept around the z axis through the quarter turn `quarter`:
// points (rho_i X_j, rho_i Y_j, z_i), weights a_i b_j; then elevated to bicubic in both directions.
inline BezierPatch revolve(const Arc& profile, int quarter, const dvec3& centre) {
    Arc turn = quarter_circle({0, 0}, 1.0, quarter);
    std::array<std::array<dvec4, 3>, 3> h;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double w = profile.w[i] * turn.w[j];
            dvec3 p(profile.p[i].x * turn.p[j].x, profile.p[i].x * turn.p[j].y, profile.p[i].y);
            h[i][j] = dvec4(w * (p + centre), w);
        }
    std::array<std::array<dvec4, 4>, 3> rows;
    for (int i = 0; i < 3; ++i) rows[i] = elevate(h[i]);
    BezierPatch out;
    for (int j = 0; j < 4; ++j) {
        auto col = elevate({rows[0][j], rows[1][j], rows[2][j]});
        for (int i = 0; i < 4; ++i) {
            out.points[4 * i + j] = dvec3(col[i]) / col[i].w;
            out.weights[4 * i + j] = col[i].w;
        }
    }
    return out;
}

// The torus (major radius R around the z axis, minor radius r) as 16 patches.
inline std::vector<BezierPatch> torus_patches(double major, double minor) {
    std::vector<BezierPatch> out;
    for (int k = 0; k < 4; ++k)
        for (int q = 0; q < 4; ++q) out.push_back(revolve(quarter_circle({major, 0}, minor, k), q, dvec3(0.0)));
    return out;
}

}  // namespace lancer::test

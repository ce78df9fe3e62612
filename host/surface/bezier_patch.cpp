#include "surface/bezier_patch.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <stdexcept>

namespace lancer::surface {
namespace {

using glm::dvec4;

// A control net of homogeneous points (w P, w) of degree (rows-1, cols-1) <= (3, 3). Derivatives
// are taken on the net (differences of control points) before evaluating, so a collapsed edge
// gives exactly zero derivative along it instead of a cancellation residue.
struct Net {
    int rows = 4;
    int cols = 4;
    std::array<dvec4, 16> h{};
    dvec4& at(int i, int j) { return h[i * cols + j]; }
    const dvec4& at(int i, int j) const { return h[i * cols + j]; }
};

Net homogeneous_net(const BezierPatch& p) {
    Net n;
    for (int k = 0; k < 16; ++k) n.h[k] = dvec4(p.weights[k] * p.points[k], p.weights[k]);
    return n;
}

Net diff_u(const Net& n) {
    Net d;
    d.rows = n.rows - 1;
    d.cols = n.cols;
    for (int i = 0; i < d.rows; ++i)
        for (int j = 0; j < d.cols; ++j) d.at(i, j) = double(d.rows) * (n.at(i + 1, j) - n.at(i, j));
    return d;
}

Net diff_v(const Net& n) {
    Net d;
    d.rows = n.rows;
    d.cols = n.cols - 1;
    for (int i = 0; i < d.rows; ++i)
        for (int j = 0; j < d.cols; ++j) d.at(i, j) = double(d.cols) * (n.at(i, j + 1) - n.at(i, j));
    return d;
}

// Bernstein basis B_k^degree(t), degree <= 3.
std::array<double, 4> bernstein(int degree, double t) {
    double s = 1.0 - t;
    switch (degree) {
        case 0:
            return {1.0, 0.0, 0.0, 0.0};
        case 1:
            return {s, t, 0.0, 0.0};
        case 2:
            return {s * s, 2.0 * s * t, t * t, 0.0};
        default:
            return {s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t};
    }
}

dvec4 eval_net(const Net& n, double u, double v) {
    auto bu = bernstein(n.rows - 1, u);
    auto bv = bernstein(n.cols - 1, v);
    dvec4 sum(0.0);
    for (int i = 0; i < n.rows; ++i) {
        dvec4 row(0.0);
        for (int j = 0; j < n.cols; ++j) row += bv[j] * n.at(i, j);
        sum += bu[i] * row;
    }
    return sum;
}

// a + t (b - a), arranged so that t = 0 gives a and t = 1 gives b exactly, and equal points stay
// equal (b - a = 0): collapsed edges stay collapsed and shared boundaries stay shared.
dvec4 lerp_exact(const dvec4& a, const dvec4& b, double t) {
    return t <= 0.5 ? a + t * (b - a) : b - (1.0 - t) * (b - a);
}

// The blossom f(t1, t2, t3) of a cubic: de Casteljau with a different parameter on each level.
dvec4 blossom(const std::array<dvec4, 4>& c, double t1, double t2, double t3) {
    dvec4 a = lerp_exact(c[0], c[1], t1), b = lerp_exact(c[1], c[2], t1), d = lerp_exact(c[2], c[3], t1);
    dvec4 e = lerp_exact(a, b, t2), f = lerp_exact(b, d, t2);
    return lerp_exact(e, f, t3);
}

// Control points of the cubic restricted to [a, b]: f(a,a,a), f(a,a,b), f(a,b,b), f(b,b,b).
std::array<dvec4, 4> sub_curve(const std::array<dvec4, 4>& c, double a, double b) {
    return {blossom(c, a, a, a), blossom(c, a, a, b), blossom(c, a, b, b), blossom(c, b, b, b)};
}

double extent(const BezierPatch& p) {
    PatchBounds b = bounds(p);
    dvec3 e = b.max - b.min;
    return std::max({e.x, e.y, e.z});
}

bool usable(const dvec3& n, double threshold) {
    double len = glm::length(n);
    return std::isfinite(len) && len > threshold;
}

}  // namespace

bool is_rational(const BezierPatch& p) {
    return std::any_of(p.weights.begin(), p.weights.end(), [](double w) { return w != 1.0; });
}

dvec3 evaluate(const BezierPatch& p, double u, double v) {
    dvec4 h = eval_net(homogeneous_net(p), u, v);
    return dvec3(h) / h.w;
}

SurfaceJet evaluate_jet(const BezierPatch& p, double u, double v) {
    Net n = homogeneous_net(p);
    Net nu = diff_u(n), nv = diff_v(n);
    dvec4 h = eval_net(n, u, v);
    dvec4 hu = eval_net(nu, u, v), hv = eval_net(nv, u, v);
    dvec4 huu = eval_net(diff_u(nu), u, v), huv = eval_net(diff_v(nu), u, v), hvv = eval_net(diff_v(nv), u, v);
    // S = N / W; differentiate N = S W. For polynomial patches the W terms are exactly zero.
    double w = h.w;
    SurfaceJet j;
    j.s = dvec3(h) / w;
    j.su = (dvec3(hu) - j.s * hu.w) / w;
    j.sv = (dvec3(hv) - j.s * hv.w) / w;
    j.suu = (dvec3(huu) - 2.0 * j.su * hu.w - j.s * huu.w) / w;
    j.suv = (dvec3(huv) - j.su * hv.w - j.sv * hu.w - j.s * huv.w) / w;
    j.svv = (dvec3(hvv) - 2.0 * j.sv * hv.w - j.s * hvv.w) / w;
    return j;
}

BezierPatch sub_patch(const BezierPatch& p, double u0, double u1, double v0, double v1) {
    Net n = homogeneous_net(p);
    for (int i = 0; i < 4; ++i) {
        auto row = sub_curve({n.at(i, 0), n.at(i, 1), n.at(i, 2), n.at(i, 3)}, v0, v1);
        for (int j = 0; j < 4; ++j) n.at(i, j) = row[j];
    }
    for (int j = 0; j < 4; ++j) {
        auto col = sub_curve({n.at(0, j), n.at(1, j), n.at(2, j), n.at(3, j)}, u0, u1);
        for (int i = 0; i < 4; ++i) n.at(i, j) = col[i];
    }
    BezierPatch out;
    const bool rational = is_rational(p);
    for (int k = 0; k < 16; ++k) {
        // A polynomial patch keeps weights of exactly 1 (w = 1 blends to 1 only up to rounding).
        out.points[k] = rational ? dvec3(n.h[k]) / n.h[k].w : dvec3(n.h[k]);
        out.weights[k] = rational ? n.h[k].w : 1.0;
    }
    return out;
}

std::pair<BezierPatch, BezierPatch> split_u(const BezierPatch& p, double u) {
    return {sub_patch(p, 0.0, u, 0.0, 1.0), sub_patch(p, u, 1.0, 0.0, 1.0)};
}

std::pair<BezierPatch, BezierPatch> split_v(const BezierPatch& p, double v) {
    return {sub_patch(p, 0.0, 1.0, 0.0, v), sub_patch(p, 0.0, 1.0, v, 1.0)};
}

PatchBounds bounds(const BezierPatch& p) {
    PatchBounds b{p.points[0], p.points[0]};
    for (const dvec3& q : p.points) {
        b.min = glm::min(b.min, q);
        b.max = glm::max(b.max, q);
    }
    return b;
}

BezierPatch transformed(const BezierPatch& p, const glm::dmat4& m) {
    // glm is column-major: m[col][row]; the bottom row is m[0..3][3].
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
        throw std::invalid_argument("transformed(): the matrix is not affine (bottom row must be 0 0 0 1)");
    BezierPatch out = p;
    for (dvec3& q : out.points) q = dvec3(m * dvec4(q, 1.0));
    return out;
}

dvec3 unit_normal(const BezierPatch& p, double u, double v) {
    if (!std::isfinite(u)) u = 0.5;
    if (!std::isfinite(v)) v = 0.5;
    const double size = extent(p);
    if (!(size > 0.0) || !std::isfinite(size)) return {0.0, 0.0, 1.0};
    // Su x Sv scales with size^2; below this it is a degenerate point, not just a small patch.
    const double tiny = 1e-10 * size * size;

    SurfaceJet j = evaluate_jet(p, u, v);
    dvec3 n = glm::cross(j.su, j.sv);
    if (usable(n, tiny)) return glm::normalize(n);

    // First-order Taylor term of N = Su x Sv from (u, v) towards the inside of the domain:
    // N(u + h e, v + k e) ~ e (h dN/du + k dN/dv). On a collapsed u-edge (Sv = Svv = 0) this is
    // h Su x Suv, the limit normal of the apex.
    double h = u < 0.5 ? 1.0 : -1.0;
    double k = v < 0.5 ? 1.0 : -1.0;
    dvec3 dn_du = glm::cross(j.suu, j.sv) + glm::cross(j.su, j.suv);
    dvec3 dn_dv = glm::cross(j.suv, j.sv) + glm::cross(j.su, j.svv);
    n = h * dn_du + k * dn_dv;
    if (usable(n, tiny)) return glm::normalize(n);

    // Higher-order degeneracy: the normal a little way inside the domain.
    for (double step : {1e-6, 1e-4, 1e-2, 1e-1}) {
        double us = std::clamp(u + h * step, 0.0, 1.0), vs = std::clamp(v + k * step, 0.0, 1.0);
        SurfaceJet js = evaluate_jet(p, us, vs);
        n = glm::cross(js.su, js.sv);
        if (usable(n, tiny)) return glm::normalize(n);
    }
    // A patch degenerate everywhere (a curve or a point): the control net's diagonals, else +z.
    n = glm::cross(control_point(p, 3, 3) - control_point(p, 0, 0), control_point(p, 0, 3) - control_point(p, 3, 0));
    if (usable(n, 0.0)) return glm::normalize(n);
    return {0.0, 0.0, 1.0};
}

}  // namespace lancer::surface

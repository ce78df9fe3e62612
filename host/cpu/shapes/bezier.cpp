// Ray/bicubic Bezier patch, exactly, by elimination (the CPU reference for patch sets):
// the ray becomes two planes; their equations on the patch, f(u, v) = g(u, v) = 0, have bidegree
// (3, 3); the resultant in v is solved as a generalized eigenproblem, 18x18 at most (bezier_algebra);
// v comes back from the univariate cubics; a 2x2 Newton polish and residual tests decide.
// The eigenvalue filters are those of the design notes on exact parametric surfaces (section
// 1.4); the acceptance test is tighter than the notes' 1e-7 (see below), and the eigenvector
// route to v is not used (it fails for multiple eigenvalues, which apexes and seams produce).
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/finite.hpp"
#include "cpu/shapes/bezier_algebra.hpp"
#include "cpu/shapes/line_crossings.hpp"
#include "cpu/shapes/ray_planes.hpp"
#include "cpu/shapes/shapes.hpp"

namespace lancer::cpu {
namespace {

using namespace bezier_algebra;
using surface::BezierPatch;

// Eigenvalues and v roots may lie this far outside [0, 1] and still be worth polishing: hits on
// patch edges and corners (shared with neighbours) must not be lost to rounding.
constexpr double kParameterSlack = 1e-6;

// Slab test against the control-point box, widened by pad: can the ray meet the patch in (t_min, t_max)?
bool may_hit_box(const surface::PatchBounds& box, double pad, const Ray& ray, double t_min, double t_max) {
    double t0 = t_min, t1 = t_max;
    for (int axis = 0; axis < 3; ++axis) {
        double lo = box.min[axis] - pad, hi = box.max[axis] + pad;
        if (ray.dir[axis] == 0.0) {
            if (ray.origin[axis] < lo || ray.origin[axis] > hi) return false;
            continue;
        }
        double ta = (lo - ray.origin[axis]) / ray.dir[axis];
        double tb = (hi - ray.origin[axis]) / ray.dir[axis];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

// Newton on (f, g) = 0 from (u, v); returns the iterate with the smallest |f| + |g| seen, so a
// diverging or stalling polish (near-singular Jacobian at a tangency) never makes things worse.
void polish(const Bicubic& f, const Bicubic& g, double& u, double& v) {
    Value a = evaluate(f, u, v), b = evaluate(g, u, v);
    double best = std::abs(a.f) + std::abs(b.f), bu = u, bv = v;
    // Up to 30 steps: quadratic convergence needs 2-4, but at a double root (a tangent ray)
    // Newton only halves the error per step, from the ~1e-8 that the eigenvalue cluster gives.
    for (int it = 0; it < 30 && best > 0.0; ++it) {
        double det = a.fu * b.fv - a.fv * b.fu;
        if (det == 0.0 || !std::isfinite(det)) break;
        double du = (a.f * b.fv - a.fv * b.f) / det;
        double dv = (a.fu * b.f - a.f * b.fu) / det;
        u -= du;
        v -= dv;
        if (!std::isfinite(u) || !std::isfinite(v) || u < -0.5 || u > 1.5 || v < -0.5 || v > 1.5) break;
        a = evaluate(f, u, v);
        b = evaluate(g, u, v);
        double r = std::abs(a.f) + std::abs(b.f);
        if (r < best) {
            best = r;
            bu = u;
            bv = v;
        }
        if (std::abs(du) + std::abs(dv) < 1e-15) break;
    }
    u = bu;
    v = bv;
}

// Newton seeds a little inside each collapsed edge (an apex). A ray passing within ~1e-8 of an
// apex makes that edge's u a highly multiple, inaccurate eigenvalue, and the candidates from the
// cluster can all miss the hit; near the apex the patch is like polar coordinates around it, where
// Newton converges from any seed in roughly the right direction. At the apex itself the Jacobian
// is singular, hence the offset. (A ray exactly through the apex is found from the eigenvalues.)
void add_apex_seeds(const BezierPatch& p, double size, std::vector<std::pair<double, double>>& out) {
    const double same = 1e-12 * size;  // collapsed to within rounding: elevated rational poles are off by ulps
    auto collapsed = [&](int first, int step) {
        for (int k = 1; k < 4; ++k)
            if (glm::length(p.points[first + k * step] - p.points[first]) > same) return false;
        return true;
    };
    constexpr double kInside = 1e-3;
    for (double s : {0.125, 0.375, 0.625, 0.875}) {
        if (collapsed(0, 1)) out.emplace_back(kInside, s);         // u = 0: row 0
        if (collapsed(12, 1)) out.emplace_back(1.0 - kInside, s);  // u = 1: row 3
        if (collapsed(0, 4)) out.emplace_back(s, kInside);         // v = 0: column 0
        if (collapsed(3, 4)) out.emplace_back(s, 1.0 - kInside);   // v = 1: column 3
    }
}

// Every (u, v) worth polishing: v recovered for each real eigenvalue u.
std::vector<std::pair<double, double>> candidates(const Bicubic& f, const Bicubic& g) {
    std::vector<std::pair<double, double>> out;
    std::vector<double> us;
    // If dggev fails (it has not been seen to) there are no candidates: a miss, not a guess.
    resultant_roots(f, g, -kParameterSlack, 1.0 + kParameterSlack, us);
    // Residuals are relative to the global coefficient scale: f(u*, .) may vanish identically
    // (a parameter line inside one of the planes), so a per-u scale would accept anything.
    const double scale = coefficient_norm(f) + coefficient_norm(g);
    std::vector<double> vs;
    for (double u : us) {
        Cubic fu = restrict_to_u(f, u), gu = restrict_to_u(g, u);
        double nf = std::abs(fu[0]) + std::abs(fu[1]) + std::abs(fu[2]) + std::abs(fu[3]);
        double ng = std::abs(gu[0]) + std::abs(gu[1]) + std::abs(gu[2]) + std::abs(gu[3]);
        if (std::max(nf, ng) <= 1e-12 * scale) {
            // The whole line u = u* lies on the ray: a collapsed edge through it, or a straight line.
            for (double v : {0.0, 0.5, 1.0}) out.emplace_back(u, v);
            continue;
        }
        const Cubic& primary = nf >= ng ? fu : gu;
        const Cubic& other = nf >= ng ? gu : fu;
        vs.clear();
        real_roots(primary, -kParameterSlack, 1.0 + kParameterSlack, vs);
        for (double v : vs)
            if (std::abs(horner(other, v)) <= 1e-6 * scale) out.emplace_back(u, v);
    }
    return out;
}

}  // namespace

std::vector<PatchHit> intersect_all(const BezierPatch& p, const Ray& ray, double t_min, double t_max) {
    const dvec3 d = ray.dir, o = ray.origin;
    const double dd = glm::dot(d, d);
    if (!(dd > 0.0) || !std::isfinite(dd) || !all_finite(o)) return {};

    const surface::PatchBounds box = surface::bounds(p);
    const dvec3 center = 0.5 * (box.min + box.max);
    const double size = std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z});
    if (!(size > 0.0) || !std::isfinite(size) || !all_finite(center)) return {};  // a point, or not finite
    const double magnitude = std::max({std::abs(box.min.x), std::abs(box.min.y), std::abs(box.min.z),
                                       std::abs(box.max.x), std::abs(box.max.y), std::abs(box.max.z)});
    if (!may_hit_box(box, 1e-9 * (size + magnitude), ray, t_min, t_max)) return {};

    // Work relative to the box centre in units of its size (conditioning), with the ray origin
    // moved along the ray to its point nearest the centre (no cancellation for distant origins).
    const dvec3 dn = d / std::sqrt(dd);
    dvec3 o_local = (o - center) / size;
    o_local -= glm::dot(o_local, dn) * dn;
    auto [n1, n2] = ray_planes(dn);
    std::array<double, 16> fb{}, gb{};
    for (int k = 0; k < 16; ++k) {
        dvec3 q = (p.points[k] - center) / size - o_local;
        fb[k] = p.weights[k] * glm::dot(n1, q);
        gb[k] = p.weights[k] * glm::dot(n2, q);
    }
    const Bicubic f = bernstein_to_power(fb), g = bernstein_to_power(gb);
    if (!(coefficient_norm(f) + coefficient_norm(g) > 0.0)) return {};  // the patch lies on the ray's line

    auto seeds = candidates(f, g);
    add_apex_seeds(p, size, seeds);
    struct Found {
        PatchHit hit;
        double residual;
    };
    std::vector<Found> found;
    for (auto [u, v] : seeds) {
        polish(f, g, u, v);
        // Clamp, then judge the clamped point in space: a root just outside the domain (rounding,
        // or Newton overshooting an apex into the patch's polynomial continuation) whose boundary
        // point is on the ray is a hit of the closed patch; any other point fails the residual.
        u = std::clamp(u, 0.0, 1.0);
        v = std::clamp(v, 0.0, 1.0);
        dvec3 s = surface::evaluate(p, u, v);
        double t = glm::dot(d, s - o) / dd;
        if (!(t > t_min && t < t_max)) continue;
        // A converged polish leaves ~1e-15 of the size; near misses (a ray passing a hair beside an
        // apex or a silhouette, where Newton stalls) must not pass for hits, or their t would be
        // off by as much as the tolerance.
        double residual = glm::length(s - (o + t * d));
        if (!(residual <= 1e-10 * size + 1e-13 * magnitude)) continue;
        found.push_back({{t, u, v}, residual});
    }

    // One hit per point: the same (u, v) found from several eigenvalues, or one point reached
    // from several parameters (a collapsed edge).
    std::sort(found.begin(), found.end(), [](const Found& a, const Found& b) { return a.hit.t < b.hit.t; });
    std::vector<PatchHit> hits;
    std::vector<double> residuals;
    const double t_eps = 1e-9 * size / std::sqrt(dd);  // 1e-9 of the patch size, in units of t
    for (const Found& x : found) {
        bool duplicate = false;
        for (std::size_t i = 0; i < hits.size() && !duplicate; ++i) {
            const PatchHit& h = hits[i];
            bool same_uv = std::abs(h.u - x.hit.u) < 1e-6 && std::abs(h.v - x.hit.v) < 1e-6;
            bool same_t = std::abs(h.t - x.hit.t) <= 1e-9 * std::abs(x.hit.t) + t_eps;
            if (same_uv || same_t) {
                duplicate = true;
                if (x.residual < residuals[i]) {
                    hits[i] = x.hit;
                    residuals[i] = x.residual;
                }
            }
        }
        if (!duplicate) {
            hits.push_back(x.hit);
            residuals.push_back(x.residual);
        }
    }
    std::sort(hits.begin(), hits.end(), [](const PatchHit& a, const PatchHit& b) { return a.t < b.t; });
    return hits;
}

std::optional<SurfaceHit> intersect(const BezierPatch& p, const Ray& ray, double t_min, double t_max) {
    std::vector<PatchHit> hits = intersect_all(p, ray, t_min, t_max);
    if (hits.empty()) return std::nullopt;
    const PatchHit& h = hits.front();
    return SurfaceHit{h.t, surface::unit_normal(p, h.u, h.v), {h.u, h.v}};
}

std::optional<SurfaceHit> intersect(const BezierSurface& s, const Ray& ray, double t_min, double t_max) {
    std::optional<SurfaceHit> best;
    for (std::size_t i = 0; i < s.patches.size(); ++i) {
        if (auto h = intersect(s.patches[i], ray, t_min, best ? best->t : t_max)) {
            best = h;
            best->part = static_cast<int>(i);
        }
    }
    return best;
}

// Every patch's hits, together: where patches meet, a ray through their edge may cross both at
// one t, which the walk takes once.
std::vector<LineCrossing> crossings_on_line(const BezierSurface& s, const Ray& ray, double t0, double t1) {
    std::vector<LineCrossing> crossings;
    for (const BezierPatch& p : s.patches)
        for (const PatchHit& h : intersect_all(p, ray, t0, t1))
            crossings.push_back({h.t, leaves_solid(s.outward, surface::unit_normal(p, h.u, h.v), ray)});
    std::sort(crossings.begin(), crossings.end(), [](const LineCrossing& a, const LineCrossing& b) { return a.t < b.t; });
    return crossings;
}

}  // namespace lancer::cpu


#pragma once
// Helpers shared by the Bezier patch tests: the pinned teapot, patch sets intersected as a
// whole (the integrator's job in the renderer; here only what the tests need), and random numbers.
#include <glm/geometric.hpp>
#include <optional>
#include <random>
#include <vector>

#include "cpu/shapes/shapes.hpp"
#include "support/test_support.hpp"
#include "surface/bezier_patch.hpp"
#include "surface/patch_file.hpp"

namespace lancer::test {

using surface::BezierPatch;

inline const std::vector<BezierPatch>& teapot() {
    static const std::vector<BezierPatch> patches = surface::read_patch_file(source_path("scenes/teapot.bpt"));
    return patches;
}

struct SetHit {
    double t, u, v;
    int patch;
};

// Every hit of every patch, nearest first (not deduplicated: shared edges give several).
inline std::vector<SetHit> all_hits(const std::vector<BezierPatch>& set, const cpu::Ray& ray, double t_min = 0.0,
                                    double t_max = 1e30) {
    std::vector<SetHit> hits;
    for (int k = 0; k < static_cast<int>(set.size()); ++k)
        for (const cpu::PatchHit& h : cpu::intersect_all(set[k], ray, t_min, t_max)) hits.push_back({h.t, h.u, h.v, k});
    std::sort(hits.begin(), hits.end(), [](const SetHit& a, const SetHit& b) { return a.t < b.t; });
    return hits;
}

// Distinct hit points along the ray: copies from patches sharing an edge or corner merged (|dt| <= 1e-9 t).
inline std::vector<double> distinct_ts(const std::vector<SetHit>& hits) {
    std::vector<double> ts;
    for (const SetHit& h : hits)
        if (ts.empty() || h.t - ts.back() > 1e-9 * std::max(1.0, std::abs(h.t))) ts.push_back(h.t);
    return ts;
}

inline std::optional<SetHit> nearest_hit(const std::vector<BezierPatch>& set, const cpu::Ray& ray, double t_min = 0.0,
                                         double t_max = 1e30) {
    std::optional<SetHit> best;
    for (int k = 0; k < static_cast<int>(set.size()); ++k)
        if (auto h = cpu::intersect(set[k], ray, t_min, best ? best->t : t_max))
            best = SetHit{h->t, h->uv.x, h->uv.y, k};
    return best;
}

inline dvec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> n;
    for (;;) {
        dvec3 d(n(rng), n(rng), n(rng));
        if (glm::length(d) > 1e-3) return glm::normalize(d);
    }
}

inline double uniform(std::mt19937& rng, double lo = 0.0, double hi = 1.0) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// A random patch with control points in [-1, 1]^3, and weights in [0.5, 2] if rational.
inline BezierPatch random_patch(std::mt19937& rng, bool rational) {
    BezierPatch p;
    for (int k = 0; k < 16; ++k) {
        p.points[k] = dvec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
        if (rational) p.weights[k] = uniform(rng, 0.5, 2.0);
    }
    return p;
}

}  // namespace lancer::test

// Benchmark (not a test): the parametric-surface pieces on the classic surfaces. For each
// surface: the GPU cells (count, time to build), the CPU reference's box tree (time to build),
// and the CPU intersector's speed on random rays through the surface's neighbourhood (best of 3
// runs, one thread), with the average and largest number of parameter boxes a ray examined.
//
//   build/bench/lancer_parametric_bench [rays=20000]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "cpu/shapes/parametric_tree.hpp"
#include "cpu/shapes/shapes.hpp"
#include "surface/parametric_cells.hpp"
#include "unit/surface_fixtures.hpp"

namespace {

using namespace lancer;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Rays from a sphere around the surface towards random points of its bounding box.
std::vector<cpu::Ray> random_rays(const surface::ParametricSurface& s, int count) {
    dvec3 lo(1e300), hi(-1e300);
    for (int i = 0; i <= 32; ++i)
        for (int j = 0; j <= 32; ++j) {
            dvec3 p = surface::evaluate_surface(s, s.u0 + (s.u1 - s.u0) * i / 32, s.v0 + (s.v1 - s.v0) * j / 32).P;
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    dvec3 centre = 0.5 * (lo + hi);
    double radius = glm::length(hi - lo);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<cpu::Ray> rays;
    for (int i = 0; i < count; ++i) {
        dvec3 o = centre + radius * glm::normalize(dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
        dvec3 aim = lo + (hi - lo) * dvec3(unit(rng), unit(rng), unit(rng));
        rays.push_back({o, glm::normalize(aim - o)});
    }
    return rays;
}

}  // namespace

int main(int argc, char** argv) {
    const int count = argc > 1 ? std::max(1, std::atoi(argv[1])) : 20000;
    std::printf("%-8s %7s %9s %9s %12s %9s %6s %9s %9s\n", "surface", "cells", "cells ms", "tree ms", "rays/s",
                "us/ray", "hits", "boxes/ray", "max boxes");
    for (const auto& spec : test::classic_surfaces()) {
        surface::ParametricSurface s = test::make_surface(spec);
        auto start = Clock::now();
        std::size_t cells = surface::subdivide_surface(s).size();
        double cells_ms = 1e3 * seconds_since(start);
        start = Clock::now();
        cpu::parametric_tree(s);
        double tree_ms = 1e3 * seconds_since(start);

        std::vector<cpu::Ray> rays = random_rays(s, count);
        double best = 1e300;
        long hits = 0, boxes = 0;
        int most = 0;
        for (int run = 0; run < 3; ++run) {
            hits = boxes = most = 0;
            start = Clock::now();
            for (const cpu::Ray& r : rays) {
                hits += cpu::intersect(s, r, 1e-9, 1e30).has_value();
                boxes += cpu::last_parametric_boxes();
                most = std::max(most, cpu::last_parametric_boxes());
            }
            best = std::min(best, seconds_since(start));
        }
        std::printf("%-8s %7zu %9.1f %9.1f %12.0f %9.2f %5.0f%% %9.1f %9d\n", spec.name.c_str(), cells, cells_ms, tree_ms,
                    count / best, 1e6 * best / count, 100.0 * hits / count, double(boxes) / count, most);
    }
}

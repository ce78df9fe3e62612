// Benchmark (not a test): the parametric-surface pieces on the classic surfaces, with Google
// Benchmark. For each surface: building the GPU's cells (and how many), building the CPU
// reference's box tree, and the CPU intersector on random rays through the surface's
// neighbourhood (one thread), with the share of hits and the parameter boxes a ray examined.
//
//   build/bench/lancer_parametric_bench [--benchmark_filter=torus] [--benchmark_repetitions=3]
#include <algorithm>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include "cpu/shapes/parametric_tree.hpp"
#include "cpu/shapes/shapes.hpp"
#include "surface/parametric_cells.hpp"
#include "unit/surface_fixtures.hpp"

namespace {

using namespace lancer;

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

void cells(benchmark::State& state, const test::SurfaceSpec& spec) {
    surface::ParametricSurface s = test::make_surface(spec);
    std::size_t count = 0;
    for (auto _ : state) count = surface::subdivide_surface(s).size();
    state.counters["cells"] = double(count);
}

void tree(benchmark::State& state, const test::SurfaceSpec& spec) {
    const surface::ParametricSurface s = test::make_surface(spec);
    for (auto _ : state) {
        surface::ParametricSurface fresh = s;  // a copy starts without the tree
        cpu::parametric_tree(fresh);
    }
}

void intersect(benchmark::State& state, const test::SurfaceSpec& spec) {
    const surface::ParametricSurface s = test::make_surface(spec);
    const std::vector<cpu::Ray> rays = random_rays(s, 4096);
    cpu::parametric_tree(s);  // built once, outside the timing
    std::size_t next = 0;
    long hits = 0, boxes = 0;
    int most = 0;
    for (auto _ : state) {
        const cpu::Ray& r = rays[next++ % rays.size()];
        hits += cpu::intersect(s, r, 1e-9, 1e30).has_value();
        boxes += cpu::last_parametric_boxes();
        most = std::max(most, cpu::last_parametric_boxes());
    }
    state.SetItemsProcessed(state.iterations());  // items/s = rays/s
    state.counters["hits"] = benchmark::Counter(double(hits), benchmark::Counter::kAvgIterations);
    state.counters["boxes/ray"] = benchmark::Counter(double(boxes), benchmark::Counter::kAvgIterations);
    state.counters["max boxes"] = double(most);
}

}  // namespace

int main(int argc, char** argv) {
    for (const auto& spec : test::classic_surfaces()) {
        benchmark::RegisterBenchmark(("cells/" + spec.name).c_str(), cells, spec)->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("cpu_tree/" + spec.name).c_str(), tree, spec)->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("cpu_intersect/" + spec.name).c_str(), intersect, spec)->Unit(benchmark::kMicrosecond);
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

// Benchmark (not a test): the CPU reference's exact ray/Bezier-patch intersection on the
// teapot, with Google Benchmark, one thread.
//   teapot_primary_rays  primary rays of a fixed 3/4 view (128x96, one per pixel), nearest hit
//                        over the 32 patches with per-patch box culling, as the renderer does;
//                        items/s = rays/s, with the ray/patch pairs past the box test per ray
//   ray_patch_pair       one such pair: the whole intersection (eigenproblem, roots, polish)
//   dggev_18x18          the 18x18 generalized eigenproblem (LAPACK dggev) alone, on random
//                        bicubics (its cost hardly depends on the values)
//
//   OPENBLAS_NUM_THREADS=1 build/bench/lancer_bench_bezier [--benchmark_filter=...]
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include "cpu/shapes/bezier_algebra.hpp"
#include "cpu/shapes/shapes.hpp"
#include "scene/camera.hpp"
#include "surface/patch_file.hpp"

namespace {

using namespace lancer;

constexpr int kWidth = 128, kHeight = 96;

struct Teapot {
    std::vector<surface::BezierPatch> patches = surface::read_patch_file(std::string(LANCER_SOURCE_DIR) + "/scenes/teapot.bpt");
    std::vector<surface::PatchBounds> boxes;
    std::vector<cpu::Ray> rays;  // one per pixel

    Teapot() {
        for (const auto& p : patches) boxes.push_back(surface::bounds(p));
        CameraSpec spec;
        spec.eye = {-5.0, -8.0, 5.0};
        spec.look_at = {0.2, 0.0, 1.4};
        spec.up = {0.0, 0.0, 1.0};
        spec.fov_deg = 30.0;
        CameraBasis cam = make_camera_basis(spec, kWidth, kHeight);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                rays.push_back({cam.eye, glm::normalize(camera_ray_direction(cam, x + 0.5, y + 0.5, kWidth, kHeight))});
    }

    bool box_hit(std::size_t k, const cpu::Ray& ray) const {
        dvec3 inv = 1.0 / ray.dir;
        dvec3 t0 = (boxes[k].min - ray.origin) * inv, t1 = (boxes[k].max - ray.origin) * inv;
        dvec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
        return std::max({lo.x, lo.y, lo.z}) <= std::min({hi.x, hi.y, hi.z});
    }
};

const Teapot& teapot() {
    static const Teapot t;
    return t;
}

void teapot_primary_rays(benchmark::State& state) {
    const Teapot& t = teapot();
    long hits = 0, pairs = 0;
    for (auto _ : state) {
        hits = pairs = 0;
        for (const cpu::Ray& ray : t.rays) {
            std::optional<cpu::SurfaceHit> best;
            for (std::size_t k = 0; k < t.patches.size(); ++k) {
                if (!t.box_hit(k, ray)) continue;
                ++pairs;
                if (auto h = cpu::intersect(t.patches[k], ray, 1e-9, best ? best->t : 1e30)) best = h;
            }
            hits += best.has_value();
        }
        benchmark::DoNotOptimize(hits);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long>(t.rays.size()));
    state.counters["hits"] = double(hits);
    state.counters["pairs/ray"] = double(pairs) / double(t.rays.size());
}

void ray_patch_pair(benchmark::State& state) {
    const Teapot& t = teapot();
    std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (ray, patch) past the box test
    for (std::size_t r = 0; r < t.rays.size(); ++r)
        for (std::size_t k = 0; k < t.patches.size(); ++k)
            if (t.box_hit(k, t.rays[r])) pairs.emplace_back(r, k);
    std::size_t next = 0;
    for (auto _ : state) {
        auto [r, k] = pairs[next++ % pairs.size()];
        benchmark::DoNotOptimize(cpu::intersect_all(t.patches[k], t.rays[r], 1e-9, 1e30));
    }
}

void dggev_18x18(benchmark::State& state) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> c(-1.0, 1.0);
    cpu::bezier_algebra::Bicubic f, g;
    for (auto& row : f)
        for (double& x : row) x = c(rng);
    for (auto& row : g)
        for (double& x : row) x = c(rng);
    std::vector<double> roots;
    for (auto _ : state) {
        roots.clear();
        cpu::bezier_algebra::resultant_roots(f, g, 0.0, 1.0, roots);
        benchmark::DoNotOptimize(roots.data());
    }
}

}  // namespace

BENCHMARK(teapot_primary_rays)->Unit(benchmark::kMillisecond);
BENCHMARK(ray_patch_pair)->Unit(benchmark::kMicrosecond);
BENCHMARK(dggev_18x18)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();

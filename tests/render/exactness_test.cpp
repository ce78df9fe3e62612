// Exact patch surfaces: the GPU's float Bezier clipping against the CPU reference's resultants
// and LAPACK, ray by ray, over views of the teapot from many directions.
#include <cmath>
#include <cstdio>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "scene/camera.hpp"
#include "scene/load_scene.hpp"
#include "support/test_support.hpp"
#include "surface/bezier_patch.hpp"

namespace lancer {
namespace {

struct Agreement {
    int hits = 0;          // both hit
    int gpu_only_miss = 0;
    int cpu_only_miss = 0;
    int wrong_t = 0;       // |t_gpu - t_cpu| > 1e-4 t
    double max_rel_t = 0;
    double max_residual = 0;  // |S(u,v) - (o + t d)| on the GPU's (patch, u, v, t)
};

TEST(Exactness, GpuBezierClippingAgreesWithLapack) {
    Scene scene = load_scene(test::source_path("scenes/teapot.toml"));
    scene.render.width = 64;
    scene.render.height = 48;
    const auto& teapot = std::get<BezierSurface>(scene.objects[1].shape);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), height(-0.5, 1.0);
    Agreement a;
    for (int view = 0; view < 6; ++view) {
        double phi = angle(rng), h = height(rng);
        scene.camera.eye = glm::dvec3(9 * std::cos(phi) * std::sqrt(1 - h * h), 1.5 + 9 * h, 9 * std::sin(phi) * std::sqrt(1 - h * h));
        scene.camera.look_at = {0.0, 1.4, 0.0};
        FloatImage gpu = test::gpu_renderer().render_hits(scene);
        FloatImage cpu = CpuRenderer().render_hits(scene);
        CameraBasis cam = make_camera_basis(scene.camera, 64, 48);
        for (int y = 0; y < 48; ++y) {
            for (int x = 0; x < 64; ++x) {
                glm::vec4 g = gpu.at(x, y), c = cpu.at(x, y);
                bool g_teapot = g.x >= 0 && g.w >= 0, c_teapot = c.x >= 0 && c.w >= 0;
                if (!g_teapot && !c_teapot) continue;
                if (g_teapot && !c_teapot) { ++a.cpu_only_miss; continue; }
                if (!g_teapot && c_teapot) { ++a.gpu_only_miss; continue; }
                ++a.hits;
                double rel = std::abs(double(g.x) - c.x) / c.x;
                a.max_rel_t = std::max(a.max_rel_t, rel);
                if (rel > 1e-4) ++a.wrong_t;
                glm::dvec3 d = glm::normalize(camera_ray_direction(cam, x + 0.5, y + 0.5, 64, 48));
                glm::dvec3 on_ray = cam.eye + double(g.x) * d;
                glm::dvec3 s = surface::evaluate(teapot.patches[static_cast<int>(g.w)], g.y, g.z);
                a.max_residual = std::max(a.max_residual, glm::length(s - on_ray));
            }
        }
    }
    std::printf("teapot: %d hits, %d GPU-only misses, %d CPU-only misses, %d wrong t, max rel t %.3g, max residual %.3g\n",
                a.hits, a.gpu_only_miss, a.cpu_only_miss, a.wrong_t, a.max_rel_t, a.max_residual);
    EXPECT_GT(a.hits, 2000);
    EXPECT_EQ(a.wrong_t, 0);
    EXPECT_LE(a.max_residual, 1e-4 * 3.15);  // scene scale: the teapot's height
    EXPECT_LE(a.gpu_only_miss + a.cpu_only_miss, a.hits / 1000);
}

}  // namespace
}  // namespace lancer

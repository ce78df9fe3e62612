// Exact patch surfaces: the GPU's float Bezier clipping against the CPU reference's resultants
// and LAPACK, ray by ray, over views of the teapot from many directions.
#include <cmath>
#include <cstdio>
#include <random>

#include <glm/geometric.hpp>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "scene/camera.hpp"
#include "support/test_support.hpp"
#include "surface/bezier_patch.hpp"

namespace lancer {
namespace {

// A ray that meets a surface at |n.d| below this grazes it: float and double may then disagree
// about whether it hits at all (a silhouette).
constexpr double kGrazing = 0.2;

struct Agreement {
    int hits = 0;          // both hit
    int gpu_only_miss = 0;
    int cpu_only_miss = 0;
    int clear_misses = 0;  // of those, rays that met the surface at |n.d| >= kGrazing
    int wrong_t = 0;       // |t_gpu - t_cpu| > 1e-4 t
    double max_rel_t = 0;
    double max_residual = 0;  // |S(u,v) - (o + t d)| on the GPU's (patch, u, v, t)
};

TEST(Exactness, GpuBezierClippingAgreesWithLapack) {
    Scene scene = test::shipped_scene("teapot", 64, 48);
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
                glm::dvec3 d = glm::normalize(camera_ray_direction(cam, x + 0.5, y + 0.5, 64, 48));
                if (g_teapot != c_teapot) {
                    // One side missed: how squarely did the ray meet the surface the other found?
                    glm::vec4 hit = g_teapot ? g : c;
                    double n_dot_d = glm::dot(d, surface::unit_normal(teapot.patches[static_cast<int>(hit.w)], hit.y, hit.z));
                    ++(g_teapot ? a.cpu_only_miss : a.gpu_only_miss);
                    if (std::abs(n_dot_d) >= kGrazing) {
                        ++a.clear_misses;
                        std::printf("  clear miss (%s hit, n.d %.3f): patch %g uv %g %g t %g\n", g_teapot ? "gpu" : "cpu",
                                    n_dot_d, hit.w, hit.y, hit.z, hit.x);
                    }
                    continue;
                }
                ++a.hits;
                double rel = std::abs(double(g.x) - c.x) / c.x;
                a.max_rel_t = std::max(a.max_rel_t, rel);
                if (rel > 1e-4) {
                    ++a.wrong_t;
                    double cn = glm::dot(d, surface::unit_normal(teapot.patches[static_cast<int>(c.w)], c.y, c.z));
                    double gn = glm::dot(d, surface::unit_normal(teapot.patches[static_cast<int>(g.w)], g.y, g.z));
                    std::printf("  wrong t: gpu %g (patch %g uv %g %g, n.d %.3f) cpu %g (patch %g uv %g %g, n.d %.3f)\n", g.x, g.w, g.y, g.z, gn, c.x, c.w, c.y, c.z, cn);
                }
                glm::dvec3 on_ray = cam.eye + double(g.x) * d;
                glm::dvec3 s = surface::evaluate(teapot.patches[static_cast<int>(g.w)], g.y, g.z);
                a.max_residual = std::max(a.max_residual, glm::length(s - on_ray));
            }
        }
    }
    std::printf("teapot: %d hits, %d GPU-only misses, %d CPU-only misses (%d not grazing), %d wrong t, max rel t %.3g, "
                "max residual %.3g\n",
                a.hits, a.gpu_only_miss, a.cpu_only_miss, a.clear_misses, a.wrong_t, a.max_rel_t, a.max_residual);
    EXPECT_GT(a.hits, 2000);
    EXPECT_EQ(a.wrong_t, 0);
    EXPECT_LE(a.max_residual, 1e-4 * 3.15);  // scene scale: the teapot's height
    // Misses on either side: none where the ray meets the surface squarely, and at most 0.1% of
    // the hits at silhouettes (|n.d| < 0.2), where float and double may round either way.
    EXPECT_EQ(a.clear_misses, 0);
    EXPECT_LE(a.gpu_only_miss + a.cpu_only_miss, a.hits / 1000);
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// Rays aimed exactly at points of edges shared by neighbouring teapot patches, and at their
// shared corners, must all hit on the GPU, where the reference hits (no cracks between
// patches or between the GPU's sub-patch leaves).
TEST(Exactness, NoCracksAlongSharedPatchEdges) {
    Scene scene = test::shipped_scene("teapot", 3, 3, 1);
    scene.objects.erase(scene.objects.begin() + 2);  // the chrome sphere would only occlude
    const auto& patches = std::get<BezierSurface>(scene.objects[1].shape).patches;
    // An edge as (patch, which): 0 = u=0, 1 = u=1, 2 = v=0, 3 = v=1.
    auto edge_points = [&](std::size_t p, int which) {
        std::array<glm::dvec3, 4> e;
        for (int k = 0; k < 4; ++k) {
            int i = which == 0 ? 0 : which == 1 ? 3 : k, j = which == 2 ? 0 : which == 3 ? 3 : k;
            e[k] = patches[p].points[4 * i + j];
        }
        return e;
    };
    auto param = [](int which, double s) {
        return which == 0 ? glm::dvec2(0, s) : which == 1 ? glm::dvec2(1, s) : which == 2 ? glm::dvec2(s, 0) : glm::dvec2(s, 1);
    };
    CpuRenderer reference;
    int aimed = 0, gpu_missed = 0, disagreed = 0;
    for (std::size_t p = 0; p < patches.size(); ++p) {
        for (int which = 0; which < 4; ++which) {
            auto e = edge_points(p, which);
            bool shared = false;
            for (std::size_t q = 0; q < patches.size() && !shared; ++q) {
                if (q == p) continue;
                for (int w = 0; w < 4 && !shared; ++w) {
                    auto f = edge_points(q, w);
                    shared = (e == f) || (e[0] == f[3] && e[1] == f[2] && e[2] == f[1] && e[3] == f[0]);
                }
            }
            if (!shared || glm::length(e[3] - e[0]) < 1e-9) continue;  // collapsed edges are apexes
            for (double s : {0.0, 0.37, 0.5, 1.0}) {
                glm::dvec2 uv = param(which, s);
                glm::dvec3 point = surface::evaluate(patches[p], uv.x, uv.y);
                glm::dvec3 normal = surface::unit_normal(patches[p], uv.x, uv.y);
                scene.camera.eye = point + 2.0 * normal + glm::dvec3(0.013, 0.021, -0.017);
                scene.camera.look_at = point;
                glm::vec4 g = test::gpu_renderer().render_hits(scene).at(1, 1);
                glm::vec4 c = reference.render_hits(scene).at(1, 1);
                ++aimed;
                if (c.x < 0) continue;  // the reference sees nothing either (cannot happen: aimed)
                if (g.x < 0) { ++gpu_missed; std::printf("  miss: patch %zu edge %d s %g point %g %g %g ref t %g\n", p, which, s, point.x, point.y, point.z, c.x); }
                else if (std::abs(g.x - c.x) > 1e-4 * c.x) { ++disagreed; std::printf("  disagree: patch %zu edge %d s %g point %g %g %g normal %g %g %g gpu t %g (patch %g uv %g %g) ref t %g (patch %g uv %g %g)\n", p, which, s, point.x, point.y, point.z, normal.x, normal.y, normal.z, g.x, g.w, g.y, g.z, c.x, c.w, c.y, c.z); }
            }
        }
    }
    std::printf("aimed %d rays at shared edges and corners: %d GPU misses, %d disagreements\n", aimed, gpu_missed, disagreed);
    EXPECT_GT(aimed, 200);
    EXPECT_EQ(gpu_missed, 0);
    EXPECT_EQ(disagreed, 0);
}

// A flat Bezier patch with evenly spaced control points is the parallelogram it spans: same
// pixels as the rectangle on the GPU (checkerboard included).
TEST(Exactness, FlatPatchIsItsRectangle) {
    const std::string common = R"(
        [render]
        width = 64
        height = 48
        [camera]
        eye = [1, 3, -4]
        look_at = [1.5, 0, 1]
        [[light]]
        position = [-3, 6, -3]
        [material.board]
        checker = { colors = [[1, 1, 1], [0.2, 0.3, 0.8]], size = 0.5 }
        [[object]]
        material = "board"
    )";
    std::string points;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) points += (points.empty() ? "" : ", ") + fmt::format("[{}, 0, {}]", i, 2.0 * j / 3.0 * 1.5);
    Scene patch = test::scene_from_text(common + "type = \"bezier\"\ncontrol_points = [" + points + "]\n");
    Scene rect = test::scene_from_text(common + "type = \"rectangle\"\ncorner = [0, 0, 0]\nedge_u = [3, 0, 0]\nedge_v = [0, 0, 3]\n");
    Rgb8Image a = to_srgb8(test::gpu_renderer().render(patch, {}));
    Rgb8Image b = to_srgb8(test::gpu_renderer().render(rect, {}));
    test::expect_same_picture("flat-patch", a, b);
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// Parametric surfaces: the GPU's search (float) against the reference's certified interval
// Newton (double), ray by ray over views of the torus from several directions, grazing rays
// included: the same root for every ray, to float's precision.
TEST(Exactness, GpuSearchAgreesWithIntervalNewtonOnTheTorus) {
    Scene scene = test::shipped_scene("torus", 48, 36);
    const auto& torus = *std::get<ParametricObject>(scene.objects[1].shape).surface;
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), height(-0.3, 0.9);
    int hits = 0, gpu_only = 0, cpu_only = 0, wrong_t = 0, grazing_disagreements = 0;
    double max_residual = 0, min_grazing = 1.0;
    for (int view = 0; view < 4; ++view) {
        double phi = angle(rng), h = height(rng);
        scene.camera.eye = glm::dvec3(4.5 * std::cos(phi) * std::sqrt(1 - h * h), 0.85 + 4.5 * h, 4.5 * std::sin(phi) * std::sqrt(1 - h * h));
        scene.camera.look_at = {0.0, 0.85, 0.0};
        CameraBasis cam = make_camera_basis(scene.camera, 48, 36);
        FloatImage gpu = test::gpu_renderer().render_hits(scene);
        FloatImage cpu = CpuRenderer().render_hits(scene);
        for (int y = 0; y < 36; ++y) {
            for (int x = 0; x < 48; ++x) {
                glm::vec4 g = gpu.at(x, y), c = cpu.at(x, y);
                // Only the torus: the floor has uv in [0,1] too, so tell them apart by the surface equation.
                glm::dvec3 d = glm::normalize(camera_ray_direction(cam, x + 0.5, y + 0.5, 48, 36));
                auto on_torus = [&](const glm::vec4& h) {
                    if (h.x < 0) return false;
                    glm::dvec3 p = cam.eye + double(h.x) * d;
                    return glm::length(surface::evaluate_surface(torus, h.y, h.z).P - p) < 1e-3;
                };
                bool gt = on_torus(g), ct = on_torus(c);
                if (!gt && !ct) continue;
                glm::dvec3 n = ct ? surface::surface_normal(torus, c.y, c.z) : surface::surface_normal(torus, g.y, g.z);
                bool grazing = std::abs(glm::dot(n, d)) < 0.2;
                if (gt != ct || (gt && std::abs(g.x - c.x) > 1e-4 * c.x)) {
                    if (grazing) {
                        ++grazing_disagreements;
                    } else if (gt != ct) {
                        if (gpu_only < 5 && !gt) std::printf("  gpu miss: cpu t %g uv %g %g; gpu t %g uv %g %g\n", c.x, c.y, c.z, g.x, g.y, g.z);
                        (gt ? cpu_only : gpu_only)++;
                    } else {
                        if (wrong_t < 5) std::printf("  wrong t: cpu t %g uv %g %g; gpu t %g uv %g %g\n", c.x, c.y, c.z, g.x, g.y, g.z);
                        ++wrong_t;
                    }
                    continue;
                }
                ++hits;
                if (gt) min_grazing = std::min(min_grazing, std::abs(glm::dot(n, d)));
                glm::dvec3 p = cam.eye + double(g.x) * d;
                max_residual = std::max(max_residual, glm::length(surface::evaluate_surface(torus, g.y, g.z).P - p));
            }
        }
    }
    std::printf("torus: %d hits agree, %d GPU-only misses, %d CPU-only misses, %d wrong t, %d grazing disagreements, "
                "max residual %.3g, smallest |n.d| of an agreeing hit %.3g\n", hits, gpu_only, cpu_only, wrong_t,
                grazing_disagreements, max_residual, min_grazing);
    EXPECT_GT(hits, 1000);
    EXPECT_EQ(gpu_only + cpu_only + wrong_t + grazing_disagreements, 0);
    EXPECT_LE(max_residual, 1e-5 * 2.7);  // scene scale: the torus's diameter
}

}  // namespace
}  // namespace lancer

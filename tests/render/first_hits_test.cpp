// The first-hit variant of both backends: the GPU's float intersections must agree with the
// reference's double ones ray by ray (t to 1e-5 relative plus a term for grazing rays, surface
// parameters to 1e-4), which
// checks the intersectors directly rather than through shading.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// Whether the reference's pixel (x, y) lies on a silhouette: a neighbour misses where it hits
// (or hits where it misses), or sees a surface at a clearly different distance (an edge in
// front of another surface, or of the plane behind it).
bool on_silhouette(const FloatImage& ref, int x, int y) {
    const glm::vec4 c = ref.pixels[static_cast<std::size_t>(y) * ref.width + x];
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= ref.width || ny >= ref.height) continue;
            const glm::vec4 n = ref.pixels[static_cast<std::size_t>(ny) * ref.width + nx];
            if ((n.x < 0) != (c.x < 0)) return true;
            if (c.x > 0 && n.x > 0 && std::abs(n.x - c.x) > 0.05f * c.x) return true;
        }
    return false;
}

class FirstHits : public testing::TestWithParam<std::string> {};

// A ray within float's rounding of a silhouette can go either way: the GPU may hit where the
// reference misses, or miss where it hits, there and only there. Such rays are rare: at most
// 0.5% of the pixels, each of them on a silhouette of the reference's picture.
TEST_P(FirstHits, GpuAgreesWithReferenceRayByRay) {
    Scene scene = test::shipped_scene(GetParam(), 96, 54);
    FloatImage gpu = test::gpu_renderer().render_hits(scene);
    FloatImage cpu = CpuRenderer().render_hits(scene);
    int hits = 0, mismatched = 0;
    for (int y = 0; y < cpu.height; ++y) {
        for (int x = 0; x < cpu.width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * cpu.width + x;
            glm::vec4 g = gpu.pixels[i], c = cpu.pixels[i];
            if ((g.x < 0) != (c.x < 0)) {
                ++mismatched;
                EXPECT_TRUE(on_silhouette(cpu, x, y)) << "pixel (" << x << ", " << y << ") is hit by one backend only";
                continue;
            }
            if (c.x < 0) continue;
            ++hits;
            // A ray meeting a surface at a grazing angle (a plane near the horizon) has a t as ill
            // conditioned as 1 / cos: float's rounding of the direction (~1e-7) moves it by about
            // 1e-7 t / cos, and cos = h / t for a plane h below the eye. These scenes' eyes are 1.2 or
            // more above their planes (measured: 0.09 at t = 7000, a fifth of the bound).
            EXPECT_NEAR(g.x, c.x, 1e-5 * c.x + 1e-8 * c.x * c.x) << "pixel " << i;
            EXPECT_NEAR(g.y, c.y, 1e-4) << "pixel " << i;
            EXPECT_NEAR(g.z, c.z, 1e-4) << "pixel " << i;
            EXPECT_EQ(g.w, c.w) << "pixel " << i;
        }
    }
    EXPECT_GT(hits, static_cast<int>(gpu.pixels.size()) / 2);
    EXPECT_LE(mismatched, static_cast<int>(gpu.pixels.size()) / 200);
}

// shadows: spheres and a rectangle; phong and many: with a plane, whose hits cover the frame.
INSTANTIATE_TEST_SUITE_P(Scenes, FirstHits, testing::Values("shadows", "phong", "many"));

}  // namespace
}  // namespace lancer

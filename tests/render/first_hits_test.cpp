// The first-hit variant of both backends: the GPU's float intersections must agree with the
// reference's double ones ray by ray (t to 1e-5 relative, surface parameters to 1e-4), which
// checks the intersectors directly rather than through shading.
#include <cmath>

#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

TEST(FirstHits, GpuAgreesWithReferenceRayByRay) {
    Scene scene = test::shipped_scene("shadows", 96, 54);
    FloatImage gpu = test::gpu_renderer().render_hits(scene);
    FloatImage cpu = CpuRenderer().render_hits(scene);
    int hits = 0, mismatched = 0;
    for (std::size_t i = 0; i < gpu.pixels.size(); ++i) {
        glm::vec4 g = gpu.pixels[i], c = cpu.pixels[i];
        if ((g.x < 0) != (c.x < 0)) {
            ++mismatched;  // a ray grazing a silhouette can go either way in float
            continue;
        }
        if (c.x < 0) continue;
        ++hits;
        EXPECT_NEAR(g.x, c.x, 1e-5 * c.x) << "pixel " << i;
        EXPECT_NEAR(g.y, c.y, 1e-4) << "pixel " << i;
        EXPECT_NEAR(g.z, c.z, 1e-4) << "pixel " << i;
        EXPECT_EQ(g.w, c.w) << "pixel " << i;
    }
    EXPECT_GT(hits, static_cast<int>(gpu.pixels.size()) / 2);
    EXPECT_EQ(mismatched, 0);
}

}  // namespace
}  // namespace lancer

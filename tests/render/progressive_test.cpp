// Progressive rendering (what `lancer view` refines with) must end on exactly the image a whole
// render makes: the passes add the same floats in the same order, so the result is compared
// bit for bit, not with the image metric.
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace lancer {
namespace {

struct Pass {
    std::uint32_t first, count;
};

FloatImage render_in_passes(const Scene& scene, const std::vector<Pass>& passes) {
    FloatImage sums;
    for (const Pass& p : passes) test::gpu_renderer().render_samples(scene, p.first, p.count, sums, {});
    return sums;
}

void expect_bit_identical(const FloatImage& a, const FloatImage& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        if (std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(glm::vec4)) != 0) ++differing;
    EXPECT_EQ(differing, 0u) << "of " << a.pixels.size() << " pixels";
}

TEST(Progressive, PassesEndOnTheWholeRenderBitForBit) {
    Scene scene = test::shipped_scene("seed", 96, 54, 3);
    FloatImage whole = test::gpu_renderer().render(scene, {});
    expect_bit_identical(render_in_passes(scene, {{0, 1}, {1, 1}, {2, 2}, {4, 5}}), whole);
    expect_bit_identical(render_in_passes(scene, {{0, 8}, {8, 1}}), whole);
}

// Area light samples are placed by a hash of the pixel and its grid sample, never of the pass:
// jittered soft shadows, spots and glass end on the same bits too.
TEST(Progressive, JitteredAreaLightsAndGlassEndOnTheWholeRender) {
    Scene scene = test::shipped_scene("lights", 64, 36, 3);
    FloatImage whole = test::gpu_renderer().render(scene, {});
    expect_bit_identical(render_in_passes(scene, {{0, 1}, {1, 3}, {4, 5}}), whole);
}

TEST(Progressive, PartialPassesHoldSumsAndRayCounts) {
    Scene scene = test::shipped_scene("seed", 32, 18, 2);
    FloatImage sums;
    test::gpu_renderer().render_samples(scene, 0, 2, sums, {});
    FloatImage whole = test::gpu_renderer().render(scene, {});
    // After 2 of 4 samples: rays counted so far are fewer than all, every pixel traced at least
    // one ray per sample, and the sum is not yet divided (sky pixels hold twice the background).
    for (std::size_t i = 0; i < sums.pixels.size(); ++i) {
        EXPECT_GE(sums.pixels[i].a, 2.0f);
        EXPECT_LT(sums.pixels[i].a, whole.pixels[i].a);
    }
    glm::vec4 corner = sums.at(0, 0);  // the top-left corner sees the sky
    EXPECT_FLOAT_EQ(corner.b, 2.0f * float(scene.render.background.b));
}

// Images taller than one band (GpuRenderer dispatches about 128 K pixels at a time) carry each
// band's sums through the shared output buffer correctly.
TEST(Progressive, SumsCarryAcrossBands) {
    Scene scene = test::scene_from_text(R"(
[render]
width = 520
height = 300
samples = 2
background = [0.2, 0.3, 0.5]
[camera]
eye = [0, 0, -4]
look_at = [0, 0, 0]
[[light]]
position = [-5, 5, -5]
[[object]]
type = "sphere"
center = [0, 0, 0]
radius = 1
)");
    FloatImage whole = test::gpu_renderer().render(scene, {});
    expect_bit_identical(render_in_passes(scene, {{0, 1}, {1, 1}, {2, 2}}), whole);
}

TEST(Progressive, ACancelledPassThrows) {
    Scene scene = test::shipped_scene("seed", 64, 36);
    FloatImage sums;
    EXPECT_THROW(test::gpu_renderer().render_samples(scene, 0, 1, sums, [](double) { return false; }), RenderCancelled);
}

}  // namespace
}  // namespace lancer

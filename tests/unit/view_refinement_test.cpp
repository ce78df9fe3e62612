// The viewer's refinement plan: passes that cover the sample grid exactly, previews, and what is
// shown between passes.
#include <cmath>

#include <gtest/gtest.h>

#include "view/refinement.hpp"

namespace lancer::view {
namespace {

TEST(Refinement, PassesCoverTheGridInOrderStartingWithOneSample) {
    for (int n = 1; n <= 16; ++n) {
        std::vector<SamplePass> passes = refinement_passes(n);
        ASSERT_FALSE(passes.empty());
        EXPECT_EQ(passes.front(), (SamplePass{0, 1}));
        std::uint32_t next = 0;
        for (std::size_t i = 0; i < passes.size(); ++i) {
            EXPECT_EQ(passes[i].first, next) << "n = " << n;
            EXPECT_GT(passes[i].count, 0u);
            // Each pass at most doubles what is done, apart from a merged tail (under twice that).
            if (i > 0) {
                EXPECT_LT(passes[i].count, 2 * passes[i].first) << "n = " << n;
            }
            next += passes[i].count;
        }
        EXPECT_EQ(next, std::uint32_t(n * n)) << "n = " << n;
        // Few passes: the sample count doubles.
        EXPECT_LE(passes.size(), std::size_t(2 + std::log2(double(n * n))));
    }
    EXPECT_EQ(refinement_passes(3), (std::vector<SamplePass>{{0, 1}, {1, 1}, {2, 2}, {4, 5}}));
    EXPECT_EQ(refinement_passes(4), (std::vector<SamplePass>{{0, 1}, {1, 1}, {2, 2}, {4, 4}, {8, 8}}));
}

// With photon mapping the viewer refines over the render's photon passes (each a camera sample
// per pixel and a photon map), so the caustics sharpen with the anti-aliasing; its preview is
// one pass of fewer photons.
TEST(Refinement, PhotonScenesRefinePassByPass) {
    Scene scene;
    scene.render.samples = 3;
    EXPECT_EQ(refinement_total(scene), 9u);
    scene.photons = PhotonSettings{};
    scene.photons->passes = 40;
    scene.photons->count = 50000;
    EXPECT_EQ(refinement_total(scene), 40u);
    std::vector<SamplePass> plan = refinement_plan(scene);
    ASSERT_FALSE(plan.empty());
    EXPECT_EQ(plan.front(), (SamplePass{0, 1}));
    std::uint32_t next = 0;
    for (const SamplePass& p : plan) {
        EXPECT_EQ(p.first, next);
        next += p.count;
    }
    EXPECT_EQ(next, 40u);
    scene.photons->first_pass = 8;  // a part of a farm render
    scene.photons->pass_count = 8;
    EXPECT_EQ(refinement_total(scene), 8u);
    Scene preview = preview_scene(scene, 4);
    ASSERT_TRUE(preview.photons);
    EXPECT_EQ(preview.photons->last_pass() - preview.photons->first_pass, 1);
    EXPECT_EQ(preview.photons->count, 50000 / 8);
}

TEST(Refinement, PreviewIsOneSampleAtAFractionOfTheSize) {
    Scene scene;
    scene.render.width = 640;
    scene.render.height = 360;
    scene.render.samples = 3;
    scene.camera.eye = {1, 2, 3};
    Scene p = preview_scene(scene, 4);
    EXPECT_EQ(p.render.width, 160);
    EXPECT_EQ(p.render.height, 90);
    EXPECT_EQ(p.render.samples, 1);
    EXPECT_EQ(p.camera.eye, scene.camera.eye);
    Scene tiny = preview_scene(scene, 1000);
    EXPECT_EQ(tiny.render.width, 1);
    EXPECT_EQ(tiny.render.height, 1);
}

TEST(Refinement, PreviewDivisorFollowsTheBudget) {
    EXPECT_EQ(preview_divisor_for(20.0, 30.0, 16), 1);    // full size fits
    EXPECT_EQ(preview_divisor_for(100.0, 30.0, 16), 2);   // a quarter of the pixels: 25 ms
    EXPECT_EQ(preview_divisor_for(130.0, 30.0, 16), 4);
    EXPECT_EQ(preview_divisor_for(1e6, 30.0, 16), 16);

    EXPECT_EQ(next_preview_divisor(2, 45.0, 30.0, 16), 4);   // too slow: half the side
    EXPECT_EQ(next_preview_divisor(16, 90.0, 30.0, 16), 16); // not past the limit
    EXPECT_EQ(next_preview_divisor(4, 20.0, 30.0, 16), 4);   // within budget
    EXPECT_EQ(next_preview_divisor(4, 3.0, 30.0, 16), 2);    // 4x the pixels still fits well
    EXPECT_EQ(next_preview_divisor(1, 1.0, 30.0, 16), 1);
}

TEST(Refinement, PartialPicturesAreTheMeanOfTheSamplesSoFar) {
    FloatImage sums(2, 1);
    sums.pixels[0] = {0.5f, 1.0f, 0.0f, 4.0f};  // two samples of (0.25, 0.5, 0)
    sums.pixels[1] = {2.0f, 2.0f, 2.0f, 2.0f};
    Rgb8Image shown = display_image(sums, 2, false);
    EXPECT_NEAR(shown.at(0, 0)[0], encode_srgb8(0.25f), 1);
    EXPECT_NEAR(shown.at(0, 0)[1], encode_srgb8(0.5f), 1);
    EXPECT_EQ(shown.at(0, 0)[2], 0);
    EXPECT_EQ(shown.at(1, 0)[2], 255);
    // The last pass has divided already: shown as it is, the bytes `lancer render` writes.
    EXPECT_EQ(display_image(sums, 9, true).bytes, to_srgb8(sums).bytes);
}

}  // namespace
}  // namespace lancer::view

namespace lancer::view {
namespace {

TEST(Refinement, PartialPicturesAreEncodedExactly) {
    FloatImage ramp(100001, 1);
    for (int i = 0; i < ramp.width; ++i) {
        float v = float(i) / 80000.0f - 0.1f;  // below 0, all of [0, 1], above 1
        ramp.pixels[i] = {v, v * 0.5f, v * 0.01f, 1.0f};
    }
    ramp.pixels[0].r = std::nanf("");
    const float scale = 1.0f / 3.0f;
    Rgb8Image shown = display_image(ramp, 3, false);
    for (int i = 0; i < ramp.width; ++i)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(shown.at(i, 0)[c], encode_srgb8(ramp.pixels[i][c] * scale)) << i << " " << c;
    EXPECT_EQ(shown.at(0, 0)[0], 0);  // NaN: black
}

}  // namespace
}  // namespace lancer::view

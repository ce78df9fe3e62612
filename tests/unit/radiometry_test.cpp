// Lights in physical units, the microfacet and photon keys as the loader reads them, the tone
// curves, and the HDR files: each value checked against the formula in docs/scene-format.md.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "image/image.hpp"
#include "optics/metals.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

const char* kCamera = R"(
    [camera]
    eye = [0, 2, -8]
    look_at = [0, 0, 0]
)";

Scene scene_with(const std::string& rest) { return test::scene_from_text(kCamera + rest); }

TEST(Radiometry, PointLightPowerBecomesIntensityOverFourPi) {
    Scene s = scene_with(R"(
        [[light]]
        position = [0, 1, 0]
        power = 100
        color = [1, 0.5, 0.25]
    )");
    const Light& l = s.lights[0];
    EXPECT_EQ(l.falloff, Falloff::InverseSquare);
    EXPECT_EQ(l.falloff_distance, 1.0);
    // I = 100 / (4 pi) W/sr; the colour at 1 m is I / pi per unit of tint.
    EXPECT_NEAR(l.emitted().r, 100.0 / (4.0 * kPi) / kPi, 1e-12);
    EXPECT_NEAR(l.emitted().g, 0.5 * 100.0 / (4.0 * kPi) / kPi, 1e-12);
    // And back: the flux is the watts times the tint.
    dvec3 flux = *radiant_flux(l);
    EXPECT_NEAR(flux.r, 100.0, 1e-9);
    EXPECT_NEAR(flux.g, 50.0, 1e-9);
    EXPECT_NEAR(flux.b, 25.0, 1e-9);
}

TEST(Radiometry, IntensityAndFalloffGiveTheSameFlux) {
    Scene s = scene_with(R"(
        [[light]]
        position = [0, 1, 0]
        intensity = 10
        [[light]]
        position = [0, 1, 0]
        color = [2, 2, 2]
        falloff = "inverse_square"
        falloff_distance = 3
        [[light]]
        position = [0, 1, 0]
    )");
    EXPECT_NEAR(radiant_flux(s.lights[0])->r, 4.0 * kPi * 10.0, 1e-9);
    EXPECT_NEAR(radiant_flux(s.lights[1])->r, 4.0 * kPi * (kPi * 2.0 * 9.0), 1e-9);  // I = pi color d0^2
    EXPECT_FALSE(radiant_flux(s.lights[2]));  // no fall-off, no finite power
}

TEST(Radiometry, SpotPowerSpreadsOverItsWeightedCone) {
    Scene s = scene_with(R"(
        [[light]]
        type = "spot"
        position = [0, 5, 0]
        direction = [0, -1, 0]
        inner_angle = 30
        outer_angle = 30
        power = 60
    )");
    const Light& l = s.lights[0];
    // A hard-edged cone of half-angle 30 degrees: Omega = 2 pi (1 - cos 30).
    double omega = 2.0 * kPi * (1.0 - std::cos(kPi / 6.0));
    EXPECT_NEAR(spot_solid_angle(l), omega, 1e-4 * omega);
    EXPECT_NEAR(l.emitted().r * kPi, 60.0 / omega, 1e-3);
    EXPECT_NEAR(radiant_flux(l)->r, 60.0, 1e-9);
    // A soft edge and tightness cover less than the whole outer cone.
    Scene soft = scene_with(R"(
        [[light]]
        type = "spot"
        position = [0, 5, 0]
        direction = [0, -1, 0]
        inner_angle = 10
        outer_angle = 30
        tightness = 5
        power = 60
    )");
    EXPECT_LT(spot_solid_angle(soft.lights[0]), omega);
    EXPECT_NEAR(radiant_flux(soft.lights[0])->r, 60.0, 1e-9);
}

TEST(MicrofacetKeys, MetalsAndGlass) {
    Scene s = scene_with(R"(
        [material.gold]
        model = "microfacet"
        metal = "gold"
        roughness = 0.3
        [material.custom]
        model = "microfacet"
        eta = [0.2, 0.9, 1.1]
        k = 3
        color = [1, 0.9, 0.9]
        [material.glass]
        model = "microfacet"
        transmission = 1
        ior = 1.5
        roughness = 0
    )");
    auto named = [&](const std::string& name) -> const Material& {
        for (const Material& m : s.materials)
            if (m.name == name) return m;
        throw std::runtime_error("no material " + name);
    };
    const Material& gold = named("gold");
    EXPECT_TRUE(gold.microfacet());
    EXPECT_EQ(gold.roughness, 0.3);
    EXPECT_NEAR(gold.alpha(), 0.09, 1e-15);
    EXPECT_EQ(gold.conductor->eta, optics::metal_preset("gold")->eta);
    const Material& custom = named("custom");
    EXPECT_EQ(custom.conductor->k, dvec3(3.0));
    EXPECT_EQ(custom.conductor->eta, dvec3(0.2, 0.9, 1.1));
    EXPECT_EQ(custom.color, dvec3(1.0, 0.9, 0.9));
    EXPECT_EQ(custom.roughness, 0.5);  // the default
    const Material& glass = named("glass");
    EXPECT_FALSE(glass.conductor);
    EXPECT_TRUE(glass.transparent());
    EXPECT_EQ(glass.roughness, 0.0);
    EXPECT_EQ(named("default").model, Model::Phong);  // the implicit default material
}

TEST(PhotonKeys, DefaultsScaleWithTheViewAndKeysOverride) {
    Scene s = scene_with(R"(
        [photons]
        count = 5000
        [[light]]
        position = [0, 5, 0]
        power = 10
    )");
    ASSERT_TRUE(s.photons);
    double view = std::sqrt(4.0 + 64.0);
    EXPECT_EQ(s.photons->count, 5000);
    EXPECT_EQ(s.photons->passes, 16);
    EXPECT_NEAR(s.photons->caustic_radius, 0.005 * view, 1e-12);
    EXPECT_NEAR(s.photons->global_radius, 0.02 * view, 1e-12);
    EXPECT_FALSE(scene_with("").photons);
    Scene t = scene_with(R"(
        [photons]
        passes = 3
        caustic_radius = 0.1
        global_radius = 0.4
        alpha = 0.5
        seed = 9
        max_bounces = 4
    )");
    EXPECT_EQ(t.photons->passes, 3);
    EXPECT_EQ(t.photons->caustic_radius, 0.1);
    EXPECT_EQ(t.photons->global_radius, 0.4);
    EXPECT_EQ(t.photons->alpha, 0.5);
    EXPECT_EQ(t.photons->seed, 9u);
    EXPECT_EQ(t.photons->max_bounces, 4);
}

TEST(PhotonKeys, RadiusShrinksAsKnausAndZwickerSay) {
    EXPECT_EQ(photon_radius(2.0, 0.7, 0), 2.0);
    // r_1^2 = r_0^2 alpha, r_2^2 = r_1^2 (1 + alpha) / 2
    EXPECT_NEAR(photon_radius(2.0, 0.7, 1), std::sqrt(4.0 * 0.7), 1e-15);
    EXPECT_NEAR(photon_radius(2.0, 0.7, 2), std::sqrt(4.0 * 0.7 * 1.7 / 2.0), 1e-15);
    // r_k^2 ~ k^(alpha - 1): the radius goes to 0, but slowly enough that the photons in it grow.
    double r100 = photon_radius(1.0, 0.7, 100), r1000 = photon_radius(1.0, 0.7, 1000);
    EXPECT_NEAR(r1000 * r1000 / (r100 * r100), std::pow(10.0, -0.3), 0.01);
}

// POV-Ray's assumed_gamma 2.2: a computed value v is the light v^2.2, which sRGB shows as about v
// (sRGB is close to gamma 2.2); 1 leaves the value linear light. Read from [render], kept in EXR.
TEST(ToneCurves, AssumedGammaTakesValuesAsLightToItsPower) {
    ToneMapping povray36;
    povray36.assumed_gamma = 2.2;
    EXPECT_FLOAT_EQ(tone_map(0.5f, povray36), std::pow(0.5f, 2.2f));
    FloatImage image(1, 1);
    image.pixels[0] = glm::vec4(0.5f, 0.25f, 0.75f, 1.0f);
    const Rgb8Image linear = to_srgb8(image), gamma = to_srgb8(image, povray36);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(gamma.bytes[c]), int(std::lround(255.0 * image.pixels[0][c])), 3) << c;
    EXPECT_EQ(int(linear.bytes[0]), 188);  // sRGB of 0.5: brighter, as lancer shows linear light
    const Scene s = test::scene_from_text("[render]\nassumed_gamma = 2.2\n[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n");
    EXPECT_DOUBLE_EQ(s.render.tone.assumed_gamma, 2.2);
    test::expect_scene_error("[render]\nassumed_gamma = 0\n[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n", 2, 17,
                             "assumed_gamma must be in [0.1, 10]");
}

TEST(ToneCurves, FollowTheirFormulas) {
    EXPECT_EQ(tone_map(0.25f, {}), 0.25f);
    EXPECT_EQ(tone_map(3.0f, {}), 3.0f);  // clamped later, by the sRGB encoder
    EXPECT_FLOAT_EQ(tone_map(0.25f, {2.0, Tone::Clamp}), 1.0f);
    EXPECT_FLOAT_EQ(tone_map(1.0f, {0.0, Tone::Reinhard}), 0.5f);
    EXPECT_FLOAT_EQ(tone_map(3.0f, {0.0, Tone::Reinhard}), 0.75f);
    EXPECT_FLOAT_EQ(tone_map(0.0f, {0.0, Tone::Aces}), 0.0f);
    EXPECT_NEAR(tone_map(1.0f, {0.0, Tone::Aces}), (2.51f + 0.03f) / (2.43f + 0.59f + 0.14f), 1e-6);
    EXPECT_LT(tone_map(7.0f, {0.0, Tone::Aces}), 1.0f);
    EXPECT_EQ(tone_map(7.5f, {0.0, Tone::Aces}), 1.0f);  // white from 7.24
    // The identity mapping leaves the 8-bit encoding exactly as it was.
    FloatImage image(3, 1);
    image.pixels = {glm::vec4(0.1f), glm::vec4(0.5f), glm::vec4(2.0f)};
    Rgb8Image a = to_srgb8(image), b = to_srgb8(image, ToneMapping{});
    EXPECT_EQ(a.bytes, b.bytes);
    EXPECT_EQ(a.bytes[3], encode_srgb8(0.5f));
    EXPECT_EQ(to_srgb8(image, {1.0, Tone::Clamp}).bytes[0], encode_srgb8(0.2f));
}

FloatImage gradient(int w, int h) {
    FloatImage image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) image.at(x, y) = glm::vec4(x * 0.37f, y * 12.5f, 1e-6f * (x + 1), 0.0f);
    image.at(0, 0) = glm::vec4(65504.0f * 4.0f, 0.0f, 1.0f / 3.0f, 0.0f);  // beyond half floats: kept
    return image;
}

TEST(HdrFiles, ExrAndPfmKeepEveryFloatAndTheirAttributes) {
    std::string dir = test::fresh_dir("hdr");
    FloatImage image = gradient(7, 5);
    write_exr(dir + "/a.exr", image, ExrInfo{3, 4, 16, {1.5, Tone::Aces, 2.2}});
    ExrInfo info;
    FloatImage exr = read_exr(dir + "/a.exr", &info);
    write_pfm(dir + "/a.pfm", image);
    FloatImage pfm = read_pfm(dir + "/a.pfm");
    for (const FloatImage* back : {&exr, &pfm}) {
        ASSERT_EQ(back->width, 7);
        ASSERT_EQ(back->height, 5);
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 7; ++x)
                for (int c = 0; c < 3; ++c) EXPECT_EQ(back->at(x, y)[c], image.at(x, y)[c]) << x << "," << y << "," << c;
    }
    EXPECT_EQ(info.first_pass, 3);
    EXPECT_EQ(info.passes, 4);
    EXPECT_EQ(info.total_passes, 16);
    EXPECT_EQ(info.tone.exposure, 1.5);
    EXPECT_EQ(info.tone.tone, Tone::Aces);
    EXPECT_EQ(info.tone.assumed_gamma, 2.2);
    // No temporary files are left beside them.
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 2);
    EXPECT_THROW(read_exr(dir + "/a.pfm"), UserError);
    EXPECT_THROW(read_pfm(dir + "/a.exr"), UserError);
}

TEST(HdrFiles, FormatComesFromTheName) {
    EXPECT_EQ(image_format_of("a.PNG"), ImageFormat::Png);
    EXPECT_EQ(image_format_of("dir.x/a.exr"), ImageFormat::Exr);
    EXPECT_EQ(image_format_of("a.pfm"), ImageFormat::Pfm);
    EXPECT_FALSE(image_format_of("a.jpg"));
    EXPECT_FALSE(image_format_of("exr"));
}

}  // namespace
}  // namespace lancer

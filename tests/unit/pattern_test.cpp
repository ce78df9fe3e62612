// Procedural patterns on the CPU (the reference): the functions docs/scene-format.md defines,
// their gradients, the colour ramp, placement and the bump rule.
#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "cpu/pattern.hpp"

namespace lancer::cpu {
namespace {

Pattern make(PatternType type, double turbulence = 0.0) {
    Pattern p;
    p.type = type;
    p.turbulence = turbulence;
    p.colors = {{0.0, dvec3(0.0)}, {1.0, dvec3(1.0)}};  // colour = f, for f in [0, 1]
    return p;
}

TEST(ColorRamp, InterpolatesBetweenStopsAndHoldsBeyondThem) {
    std::vector<ColorStop> ramp = {{0.2, {1, 0, 0}}, {0.6, {0, 1, 0}}, {1.0, {0, 0, 1}}};
    EXPECT_EQ(ramp_color(ramp, -1.0), dvec3(1, 0, 0));
    EXPECT_EQ(ramp_color(ramp, 0.2), dvec3(1, 0, 0));
    EXPECT_NEAR(glm::length(ramp_color(ramp, 0.4) - dvec3(0.5, 0.5, 0)), 0.0, 1e-15);
    EXPECT_EQ(ramp_color(ramp, 0.6), dvec3(0, 1, 0));
    EXPECT_NEAR(glm::length(ramp_color(ramp, 0.8) - dvec3(0, 0.5, 0.5)), 0.0, 1e-15);
    EXPECT_EQ(ramp_color(ramp, 1.5), dvec3(0, 0, 1));
}

TEST(ColorRamp, EqualStopsMakeASharpEdge) {
    std::vector<ColorStop> ramp = {{0.0, {1, 1, 1}}, {0.5, {1, 1, 1}}, {0.5, {0, 0, 0}}, {1.0, {0, 0, 0}}};
    EXPECT_EQ(ramp_color(ramp, 0.4999), dvec3(1.0));
    EXPECT_EQ(ramp_color(ramp, 0.5), dvec3(0.0));
    EXPECT_EQ(ramp_color(ramp, 0.9), dvec3(0.0));
}

TEST(Patterns, MarbleWithoutTurbulenceIsASineAcrossX) {
    Pattern marble = make(PatternType::Marble);
    for (double x : {0.0, 0.1, 0.25, 0.5, 0.75, 1.3, -2.6})
        EXPECT_NEAR(pattern_value(marble, {x, 3.7, -1.2}).value, 0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * x), 1e-12);
}

TEST(Patterns, WoodWithoutTurbulenceIsATriangleWaveOfTheRadiusAboutZ) {
    Pattern wood = make(PatternType::Wood);
    EXPECT_NEAR(pattern_value(wood, {0.5, 0.0, 9.0}).value, 1.0, 1e-12);    // half way through a ring
    EXPECT_NEAR(pattern_value(wood, {0.0, 1.0, -3.0}).value, 0.0, 1e-12);   // on a ring boundary
    EXPECT_NEAR(pattern_value(wood, {0.15, 0.2, 0.0}).value, 0.5, 1e-12);   // radius 0.25
    EXPECT_NEAR(pattern_value(wood, {0.45, -0.6, 2.0}).value, 0.5, 1e-12);  // radius 0.75
}

TEST(Patterns, NoiseAndTurbulenceAreTheDocumentedSums) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> d(-20.0, 20.0);
    Pattern noise = make(PatternType::Noise);
    Pattern turbulence = make(PatternType::Turbulence);
    turbulence.octaves = 3;
    turbulence.omega = 0.4;
    turbulence.lambda = 2.5;
    for (int i = 0; i < 1000; ++i) {
        dvec3 q(d(rng), d(rng), d(rng));
        EXPECT_NEAR(pattern_value(noise, q).value, 0.5 + 0.5 * perlin_noise(q).value, 1e-15);
        double sum = std::abs(perlin_noise(q).value) + 0.4 * std::abs(perlin_noise(2.5 * q).value) +
                     0.16 * std::abs(perlin_noise(6.25 * q).value);
        EXPECT_NEAR(pattern_value(turbulence, q).value, sum, 1e-12);
        double f = pattern_value(noise, q).value;
        EXPECT_TRUE(f >= 0.0 && f <= 1.0) << f;
    }
}

TEST(Patterns, GradientsAreTheDerivatives) {
    std::mt19937 rng(6);
    std::uniform_real_distribution<double> d(-5.0, 5.0);
    const double h = 1e-7;
    for (PatternType type : {PatternType::Noise, PatternType::Turbulence, PatternType::Marble, PatternType::Wood}) {
        Pattern p = make(type, 0.7);
        int checked = 0, agreeing = 0;
        for (int i = 0; i < 2000; ++i) {
            dvec3 q(d(rng), d(rng), d(rng));
            dvec3 g = pattern_value(p, q).gradient;
            bool ok = true;
            for (int a = 0; a < 3; ++a) {
                dvec3 e(0.0);
                e[a] = h;
                double numeric = (pattern_value(p, q + e).value - pattern_value(p, q - e).value) / (2.0 * h);
                ok = ok && std::abs(numeric - g[a]) <= 1e-4 * std::max(1.0, std::abs(g[a]));
            }
            ++checked;
            agreeing += ok;
        }
        // Turbulence (|noise|) and wood (a triangle wave) have kinks, where a central difference
        // straddles two slopes: only points within h of one may disagree.
        EXPECT_GE(agreeing, checked - 2) << "pattern type " << int(type);
    }
}

TEST(Patterns, PlacementMovesThePattern) {
    Pattern marble = make(PatternType::Marble, 0.8);
    Pattern placed = marble;
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), dvec3(1.0, -2.0, 0.5));
    m = m * glm::rotate(glm::dmat4(1.0), 0.7, dvec3(0, 1, 0));
    m = m * glm::scale(glm::dmat4(1.0), dvec3(2.0));
    placed.to_world = m;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> d(-3.0, 3.0);
    for (int i = 0; i < 200; ++i) {
        dvec3 q(d(rng), d(rng), d(rng));
        dvec3 world = dvec3(m * glm::dvec4(q, 1.0));  // where pattern point q went
        EXPECT_NEAR(pattern_color(placed, world).r, pattern_color(marble, q).r, 1e-9);
    }
}

TEST(Bump, TiltsTheNormalAgainstTheGradientAndKeepsItUnit) {
    Bump bump;
    bump.pattern = make(PatternType::Wood);  // gradient (x, y, 0) / r times +-2, known exactly
    bump.amount = 0.3;
    dvec3 n(0.0, 0.0, -1.0);
    dvec3 p(0.1, 0.2, 0.0);  // radius 0.2236: on the rising half of a ring, f = 2r
    double r = glm::length(p);
    dvec3 g = 2.0 * dvec3(p.x / r, p.y / r, 0.0);
    dvec3 expected = glm::normalize(n - 0.3 * g);
    dvec3 got = bumped_normal(bump, p, n);
    EXPECT_NEAR(glm::length(got - expected), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(got), 1.0, 1e-12);
    bump.amount = 0.0;
    EXPECT_NEAR(glm::length(bumped_normal(bump, p, n) - n), 0.0, 1e-15);
}

TEST(Bump, KeepsItsDepthWhenTheBumpIsScaled) {
    // Scaling a bump's pattern by s spreads it out by s and leaves the tilts as they were.
    Bump small, large;
    small.pattern = make(PatternType::Noise);
    large.pattern = make(PatternType::Noise);
    large.pattern.to_world = glm::scale(glm::dmat4(1.0), dvec3(3.0));
    dvec3 n = glm::normalize(dvec3(0.3, 1.0, -0.2));
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> d(-4.0, 4.0);
    for (int i = 0; i < 100; ++i) {
        dvec3 p(d(rng), d(rng), d(rng));
        EXPECT_NEAR(glm::length(bumped_normal(small, p, n) - bumped_normal(large, 3.0 * p, n)), 0.0, 1e-12);
    }
}

}  // namespace
}  // namespace lancer::cpu

// Improved Perlin noise on the CPU (the reference): exactly Ken Perlin's function, zero on the
// lattice, continuous, bounded, and with the gradient it claims.
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cpu/noise.hpp"
#include "support/perlin_reference.hpp"

namespace lancer::cpu {
namespace {

using test::reference_noise;

glm::dvec3 random_point(std::mt19937& rng, double extent) {
    std::uniform_real_distribution<double> d(-extent, extent);
    return {d(rng), d(rng), d(rng)};
}

TEST(PerlinNoise, IsKenPerlinsReferenceFunction) {
    std::mt19937 rng(1);
    for (int i = 0; i < 20000; ++i) {
        glm::dvec3 p = random_point(rng, 300.0);
        EXPECT_NEAR(perlin_noise(p).value, reference_noise(p), 1e-12) << p.x << " " << p.y << " " << p.z;
    }
}

TEST(PerlinNoise, IsZeroAtEveryLatticePoint) {
    for (int x = -6; x <= 6; ++x)
        for (int y = -6; y <= 6; ++y)
            for (int z = -6; z <= 6; ++z) EXPECT_EQ(perlin_noise({x * 17.0, y * 3.0, z + 250.0}).value, 0.0);
}

TEST(PerlinNoise, IsContinuousAcrossCellBoundaries) {
    // Approaching an integer plane from both sides gives the same value (the fade makes the
    // cells meet with matching value and slope).
    std::mt19937 rng(2);
    for (int i = 0; i < 2000; ++i) {
        glm::dvec3 p = random_point(rng, 50.0);
        p.x = std::floor(p.x);
        const double e = 1e-9;
        NoiseSample below = perlin_noise(p - glm::dvec3(e, 0, 0)), above = perlin_noise(p + glm::dvec3(e, 0, 0));
        EXPECT_NEAR(below.value, above.value, 1e-8);
        EXPECT_NEAR(glm::length(below.gradient - above.gradient), 0.0, 1e-6);
    }
    // Lipschitz: nearby points have nearby values everywhere.
    for (int i = 0; i < 20000; ++i) {
        glm::dvec3 p = random_point(rng, 50.0), q = p + random_point(rng, 1e-3);
        EXPECT_LE(std::abs(perlin_noise(p).value - perlin_noise(q).value), 4.0 * glm::length(p - q));
    }
}

TEST(PerlinNoise, StaysWithinItsDocumentedRange) {
    // docs/scene-format.md: noise is in [-1, 1]. Random points, then a climb from the largest.
    std::mt19937 rng(3);
    double lo = 0.0, hi = 0.0;
    for (int i = 0; i < 1000000; ++i) {
        double n = perlin_noise(random_point(rng, 256.0)).value;
        lo = std::min(lo, n);
        hi = std::max(hi, n);
    }
    EXPECT_GE(lo, -1.0);
    EXPECT_LE(hi, 1.0);
    EXPECT_LT(lo, -0.8);  // and it uses most of that range
    EXPECT_GT(hi, 0.8);
}

TEST(PerlinNoise, GradientIsTheDerivative) {
    std::mt19937 rng(4);
    const double h = 1e-6;
    for (int i = 0; i < 5000; ++i) {
        glm::dvec3 p = random_point(rng, 100.0);
        glm::dvec3 g = perlin_noise(p).gradient;
        for (int a = 0; a < 3; ++a) {
            glm::dvec3 e(0.0);
            e[a] = h;
            double numeric = (perlin_noise(p + e).value - perlin_noise(p - e).value) / (2.0 * h);
            EXPECT_NEAR(g[a], numeric, 1e-6) << "axis " << a;
        }
    }
}

}  // namespace
}  // namespace lancer::cpu

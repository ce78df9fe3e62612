// fog_depth (scene/fog.cpp): POV-Ray's ground fog integrated in closed form, against the
// integral itself (composite Simpson over a thousand pieces) along segments that start below,
// inside and above the offset, go up, down and level, short and long; and the rays that meet
// nothing: finite going up (they leave the fog), infinite level or down.
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/scene.hpp"

namespace lancer {
namespace {

double density(const Fog::Ground& g, const dvec3& p) {
    const double y = (glm::dot(p, g.up) - g.offset) / g.altitude;
    return y <= 0.0 ? 1.0 : 1.0 / (1.0 + y * y);
}

double simpson(const Fog::Ground& g, const dvec3& from, const dvec3& dir, double length) {
    const int n = 2000;
    double sum = density(g, from) + density(g, from + length * dir);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * density(g, from + (length * i / n) * dir);
    return sum * length / (3.0 * n);
}

TEST(FogDepth, GroundFogIsTheIntegralOfItsDensity) {
    Fog fog;
    fog.ground = Fog::Ground{glm::normalize(dvec3(0.1, 1.0, -0.2)), 0.7, 0.4};
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 300; ++i) {
        const dvec3 from(3.0 * u(rng), 0.7 + 2.0 * u(rng), 3.0 * u(rng));
        dvec3 dir(u(rng), i % 10 == 0 ? 0.0 : 0.3 * u(rng), u(rng));  // some level along y
        dir = glm::normalize(dir);
        const double length = 0.01 + 6.0 * (u(rng) + 1.0);
        const double exact = simpson(*fog.ground, from, dir, length);
        // Simpson's rule meets the kink at the offset within its pieces: 1e-6 of the depth.
        EXPECT_NEAR(fog_depth(fog, from, dir, length), exact, 1e-6 * exact + 1e-12) << "segment " << i;
    }
    Fog constant;
    EXPECT_EQ(fog_depth(constant, dvec3(0.0), dvec3(0.0, 1.0, 0.0), 3.5), 3.5);
}

TEST(FogDepth, RaysThatMeetNothingLeaveTheFogOnlyGoingUp) {
    Fog fog;
    fog.ground = Fog::Ground{dvec3(0.0, 1.0, 0.0), 0.0, 1.0};
    const dvec3 up = glm::normalize(dvec3(1.0, 1.0, 0.0));
    const double far = fog_depth(fog, dvec3(0.0, -1.0, 0.0), up, INFINITY);
    // Below the offset 1 / sin 45 of length to Y = 0, then atan from 0 to infinity: pi / 2.
    EXPECT_NEAR(far, (1.0 + M_PI / 2.0) * std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(fog_depth(fog, dvec3(0.0, 2.0, 0.0), up, 1e9), fog_depth(fog, dvec3(0.0, 2.0, 0.0), up, INFINITY), 1e-8);
    EXPECT_TRUE(std::isinf(fog_depth(fog, dvec3(0.0, 2.0, 0.0), dvec3(1.0, 0.0, 0.0), INFINITY)));
    EXPECT_TRUE(std::isinf(fog_depth(fog, dvec3(0.0, 2.0, 0.0), glm::normalize(dvec3(1.0, -0.1, 0.0)), INFINITY)));
}

}  // namespace
}  // namespace lancer

// The CPU reference's lights: the integer hash both backends share bit for bit, area light
// samples, the spot cone and the inverse-square fall-off, against values worked out by hand.
#include <cmath>
#include <set>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "cpu/lights.hpp"

namespace lancer::cpu {
namespace {

// Values of PCG's output permutation computed outside lancer (Python, 32-bit wrapping
// arithmetic): the shader's hash must give the same bits (tests/render's area light scenes).
TEST(LightHash, IsPcgsOutputPermutation) {
    EXPECT_EQ(hash_u32(0u), 129708002u);
    EXPECT_EQ(hash_u32(1u), 2831084092u);
    EXPECT_EQ(hash_u32(12345u), 4099845390u);
    EXPECT_EQ(hash_u32(0xffffffffu), 3861530882u);
}

Light area_light(int n, bool jitter) {
    Light l;
    l.type = LightType::Area;
    l.position = {1.0, 5.0, 2.0};
    l.edge_u = {2.0, 0.0, 0.0};
    l.edge_v = {0.0, 0.0, 4.0};
    l.samples = n;
    l.jitter = jitter;
    return l;
}

TEST(AreaLight, UnjitteredSamplesSitAtTheCellCentres) {
    Light l = area_light(4, false);
    ASSERT_EQ(light_sample_count(l), 16);
    for (int s = 0; s < 16; ++s) {
        dvec3 q = light_sample_position(l, 0, s, 12345u);
        double a = ((s % 4) + 0.5) / 4.0 - 0.5, b = ((s / 4) + 0.5) / 4.0 - 0.5;
        EXPECT_EQ(q, l.position + a * l.edge_u + b * l.edge_v) << "sample " << s;
    }
}

TEST(AreaLight, JitteredSamplesStayInTheirCellsAndDependOnTheSeed) {
    Light l = area_light(3, true);
    std::set<double> xs;
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        for (int s = 0; s < 9; ++s) {
            dvec3 q = light_sample_position(l, 2, s, seed);
            double a = (q.x - l.position.x) / 2.0 + 0.5, b = (q.z - l.position.z) / 4.0 + 0.5;  // in [0, 1]
            EXPECT_GE(a * 3.0, s % 3);
            EXPECT_LT(a * 3.0, s % 3 + 1);
            EXPECT_GE(b * 3.0, s / 3);
            EXPECT_LT(b * 3.0, s / 3 + 1);
            EXPECT_EQ(q.y, l.position.y);
            xs.insert(q.x);
        }
    }
    EXPECT_EQ(xs.size(), 27u);  // no two samples alike across seeds
    EXPECT_EQ(light_sample_position(l, 2, 4, 7u), light_sample_position(l, 2, 4, 7u));  // deterministic
}

TEST(AreaLight, EachSampleCarriesItsShareOfTheColour) {
    Light l = area_light(4, false);
    l.color = {1.6, 0.8, 3.2};
    EXPECT_EQ(light_intensity(l, l.position, {0, 0, 0}, 16), dvec3(0.1, 0.05, 0.2));
}

Light spot(double inner, double outer, double tightness) {
    Light l;
    l.type = LightType::Spot;
    l.position = {0.0, 4.0, 0.0};
    l.direction = {0.0, -1.0, 0.0};
    l.inner_angle_deg = inner;
    l.outer_angle_deg = outer;
    l.tightness = tightness;
    return l;
}

// The floor point at `deg` degrees off the spot's axis.
dvec3 floor_point(double deg) { return {4.0 * std::tan(deg * kPi / 180.0), 0.0, 0.0}; }

TEST(SpotLight, FullInsideTheInnerConeDarkOutsideTheOuterCubicBetween) {
    Light l = spot(20.0, 40.0, 0.0);
    EXPECT_EQ(light_intensity(l, l.position, floor_point(0.0), 1), dvec3(1.0));
    EXPECT_EQ(light_intensity(l, l.position, floor_point(19.9), 1), dvec3(1.0));
    EXPECT_EQ(light_intensity(l, l.position, floor_point(40.1), 1), dvec3(0.0));
    EXPECT_EQ(light_intensity(l, l.position, floor_point(80.0), 1), dvec3(0.0));
    EXPECT_EQ(light_intensity(l, l.position, {0.0, 8.0, 0.0}, 1), dvec3(0.0));  // behind the light
    double c = std::cos(30.0 * kPi / 180.0), lo = std::cos(40.0 * kPi / 180.0), hi = std::cos(20.0 * kPi / 180.0);
    double t = (c - lo) / (hi - lo);
    EXPECT_NEAR(light_intensity(l, l.position, floor_point(30.0), 1).g, 3 * t * t - 2 * t * t * t, 1e-12);
}

TEST(SpotLight, TightnessNarrowsTheBeamAsAPowerOfTheCosine) {
    Light l = spot(60.0, 60.0, 10.0);
    double c = std::cos(25.0 * kPi / 180.0);
    EXPECT_NEAR(light_intensity(l, l.position, floor_point(25.0), 1).r, std::pow(c, 10.0), 1e-12);
}

TEST(Falloff, InverseSquareHasTheColourAtTheReferenceDistance) {
    Light l;
    l.position = {0.0, 0.0, 0.0};
    l.color = {0.5, 1.0, 2.0};
    l.falloff = Falloff::InverseSquare;
    l.falloff_distance = 3.0;
    EXPECT_EQ(light_intensity(l, l.position, {0.0, 3.0, 0.0}, 1), l.color);
    dvec3 twice = light_intensity(l, l.position, {0.0, 0.0, -6.0}, 1);
    EXPECT_NEAR(twice.b, 0.5, 1e-15);  // twice as far: a quarter
    dvec3 near = light_intensity(l, l.position, {1.0, 0.0, 0.0}, 1);
    EXPECT_NEAR(near.r, 4.5, 1e-15);  // 3x nearer: 9x brighter
    l.falloff = Falloff::None;
    EXPECT_EQ(light_intensity(l, l.position, {0.0, 100.0, 0.0}, 1), l.color);
}

}  // namespace
}  // namespace lancer::cpu

// The CPU reference's dielectric maths against textbook values: Fresnel at normal incidence and
// at the critical angle, Snell's law, Beer-Lambert, and the media a ray is inside.
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "cpu/dielectric.hpp"

namespace lancer::cpu {
namespace {

double normal_incidence(double n1, double n2) { return std::pow((n1 - n2) / (n1 + n2), 2.0); }

TEST(Fresnel, NormalIncidenceIsTheTextbookValueFromEitherSide) {
    const double pairs[][2] = {{1.0, 1.5}, {1.5, 1.0}, {1.0, 1.33}, {1.5, 1.33}, {1.33, 2.4}, {2.4, 1.0}};
    for (const auto& [n1, n2] : pairs) {
        Fresnel f = fresnel(1.0, n1, n2);
        EXPECT_NEAR(f.reflectance, normal_incidence(n1, n2), 1e-15) << n1 << " -> " << n2;
        EXPECT_DOUBLE_EQ(f.cos_t, 1.0);
    }
    EXPECT_NEAR(fresnel(1.0, 1.0, 1.5).reflectance, 0.04, 1e-15);  // air to glass: 4%
    EXPECT_NEAR(fresnel(0.3, 1.5, 1.5).reflectance, 0.0, 1e-15);  // no interface, no reflection
}

// Light crossing an interface one way is reflected as much as light going back along the
// refracted path (Stokes-Helmholtz reciprocity).
TEST(Fresnel, ReflectanceIsTheSameBothWaysAlongOnePath) {
    for (double deg = 0.0; deg < 89.0; deg += 7.0) {
        double cos_i = std::cos(deg * kPi / 180.0);
        Fresnel in = fresnel(cos_i, 1.0, 1.5);
        Fresnel out = fresnel(in.cos_t, 1.5, 1.0);
        EXPECT_NEAR(in.reflectance, out.reflectance, 1e-12) << deg << " degrees";
        EXPECT_NEAR(out.cos_t, cos_i, 1e-12);
    }
}

TEST(Fresnel, TotalInternalReflectionBeyondTheCriticalAngle) {
    const double n1 = 1.5, n2 = 1.0;
    const double critical = std::asin(n2 / n1);  // 41.8 degrees
    Fresnel below = fresnel(std::cos(critical - 1e-6), n1, n2);
    EXPECT_LT(below.reflectance, 1.0);
    EXPECT_GT(below.reflectance, 0.99);  // it climbs to 1 as the angle nears the critical angle
    for (double extra : {1e-6, 0.1, 0.5, 0.8}) {
        Fresnel beyond = fresnel(std::cos(critical + extra), n1, n2);
        EXPECT_EQ(beyond.reflectance, 1.0) << "critical angle + " << extra << " rad";
        EXPECT_EQ(beyond.cos_t, 0.0);
    }
    // Going into the denser medium there is no critical angle.
    EXPECT_LT(fresnel(std::cos(1.5), n2, n1).reflectance, 1.0);
}

TEST(Fresnel, BrewsterAngleReflectsOnlyTheSPolarisation) {
    // At Brewster's angle tan(theta) = n2 / n1 the p amplitude vanishes: R = r_s^2 / 2.
    const double n1 = 1.0, n2 = 1.5;
    double theta = std::atan(n2 / n1);
    double cos_t = std::cos(std::asin(n1 * std::sin(theta) / n2));
    double r_s = (n1 * std::cos(theta) - n2 * cos_t) / (n1 * std::cos(theta) + n2 * cos_t);
    EXPECT_NEAR(fresnel(std::cos(theta), n1, n2).reflectance, r_s * r_s / 2.0, 1e-15);
}

TEST(Refract, FollowsSnellsLawInThePlaneOfIncidence) {
    const dvec3 n(0.0, 1.0, 0.0);  // facing the incoming ray, which goes down
    for (double deg : {0.0, 10.0, 30.0, 60.0, 85.0}) {
        double theta = deg * kPi / 180.0;
        dvec3 d(std::sin(theta), -std::cos(theta), 0.0);
        const double n1 = 1.0, n2 = 1.5;
        double cos_i = -glm::dot(d, n);
        Fresnel f = fresnel(cos_i, n1, n2);
        dvec3 t = refract(d, n, n1 / n2, cos_i, f.cos_t);
        EXPECT_NEAR(glm::length(t), 1.0, 1e-15);
        EXPECT_NEAR(n1 * std::sin(theta), n2 * t.x, 1e-15) << deg;  // n1 sin(theta1) = n2 sin(theta2)
        EXPECT_LT(t.y, 0.0);                                         // on through the surface
        EXPECT_EQ(t.z, 0.0);
    }
}

TEST(BeerLambert, LeavesExpOfMinusAbsorptionTimesDistance) {
    dvec3 left = beer_lambert({0.5, 1.0, 0.0}, 2.0);
    EXPECT_DOUBLE_EQ(left.r, std::exp(-1.0));
    EXPECT_DOUBLE_EQ(left.g, std::exp(-2.0));
    EXPECT_EQ(left.b, 1.0);
    dvec3 far = beer_lambert({0.5, 0.0, 1e-9}, std::numeric_limits<double>::infinity());
    EXPECT_EQ(far, dvec3(0.0, 1.0, 0.0));  // an absorbing medium that never ends lets nothing through
}

TEST(Media, CrossingASurfaceTogglesBeingInsideItsMaterial) {
    Media air;
    EXPECT_FALSE(air.innermost());
    Media glass = air.crossed(7);
    EXPECT_EQ(glass.innermost(), 7u);
    Media liquid = glass.crossed(3);  // the liquid inside the glass
    EXPECT_EQ(liquid.innermost(), 3u);
    Media liquid_only = liquid.crossed(7);  // the glass's inner wall, inside the liquid
    EXPECT_EQ(liquid_only.innermost(), 3u);
    EXPECT_EQ(liquid_only.size(), 1u);
    EXPECT_FALSE(liquid_only.crossed(3).innermost());  // out into the air
    EXPECT_EQ(glass.crossed(7).size(), 0u);
}

TEST(Media, FullStackForgetsTheOutermost) {
    Media m;
    for (std::uint32_t i = 1; i <= Media::kDepth; ++i) m = m.crossed(i);
    EXPECT_EQ(m.size(), Media::kDepth);
    Media deeper = m.crossed(99);
    EXPECT_EQ(deeper.size(), Media::kDepth);
    EXPECT_EQ(deeper.innermost(), 99u);
    // Leaving everything that is remembered ends in the air: material 1 was forgotten.
    for (std::uint32_t i : {99u, 4u, 3u, 2u}) deeper = deeper.crossed(i);
    EXPECT_FALSE(deeper.innermost());
}

TEST(ThinSheet, OnlyRectanglesAreThin) {
    EXPECT_TRUE(is_thin_sheet(Rectangle{}));
    EXPECT_FALSE(is_thin_sheet(Sphere{}));
    EXPECT_FALSE(is_thin_sheet(Plane{}));
    EXPECT_FALSE(is_thin_sheet(Box{}));
}

}  // namespace
}  // namespace lancer::cpu

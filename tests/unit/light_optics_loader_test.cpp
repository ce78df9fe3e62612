// The scene loader's light types and optics keys: defaults, conversions (an area light's corner to
// its centre, a spot's point_at to its direction) and how animations move each light type.
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/animation.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

const char* kCamera = R"(
    [camera]
    eye = [0, 2, -8]
    look_at = [0, 0, 0]
)";

Scene scene_with(const std::string& rest) { return test::scene_from_text(kCamera + rest); }

TEST(OpticsKeys, DefaultsAreOpaqueWithAPhongHighlight) {
    Scene s = scene_with("[material.m]\ncolor = [1, 0, 0]\n");
    const Material& m = s.materials[0];
    EXPECT_FALSE(m.transparent());
    EXPECT_EQ(m.transmission, dvec3(0.0));
    EXPECT_EQ(m.ior, 1.0);
    EXPECT_EQ(m.absorption, dvec3(0.0));
    EXPECT_EQ(m.highlight, Highlight::Phong);
}

TEST(OpticsKeys, ReadsTransmissionAsScalarOrColour) {
    Scene s = scene_with(R"(
        [material.a]
        transmission = 0.9
        ior = 1.33
        absorption = 0.5
        highlight = "blinn"
        [material.b]
        transmission = [1, 0.5, 0]
        absorption = [0.1, 0.2, 0.3]
    )");
    const Material& a = s.materials[0];
    EXPECT_EQ(a.transmission, dvec3(0.9));
    EXPECT_EQ(a.ior, 1.33);
    EXPECT_EQ(a.absorption, dvec3(0.5));
    EXPECT_EQ(a.highlight, Highlight::Blinn);
    const Material& b = s.materials[1];
    EXPECT_TRUE(b.transparent());
    EXPECT_EQ(b.transmission, dvec3(1, 0.5, 0));
    EXPECT_EQ(b.absorption, dvec3(0.1, 0.2, 0.3));
    EXPECT_EQ(b.ior, 1.0);  // transparent without bending: a colour filter
}

TEST(LightKeys, PointLightDefaults) {
    Scene s = scene_with("[[light]]\nposition = [1, 2, 3]\n");
    const Light& l = s.lights[0];
    EXPECT_EQ(l.type, LightType::Point);
    EXPECT_EQ(l.falloff, Falloff::None);
    EXPECT_EQ(l.color, dvec3(1.0));
}

TEST(LightKeys, InverseSquareFalloffKeepsItsDistance) {
    Scene s = scene_with("[[light]]\nposition = [0, 5, 0]\nfalloff = \"inverse_square\"\nfalloff_distance = 7.5\n");
    EXPECT_EQ(s.lights[0].falloff, Falloff::InverseSquare);
    EXPECT_EQ(s.lights[0].falloff_distance, 7.5);
}

TEST(LightKeys, SpotAimsAtPointAtOrAlongItsDirection) {
    Scene s = scene_with(R"(
        [[light]]
        type = "spot"
        position = [0, 4, 0]
        point_at = [3, 0, 0]
        [[light]]
        type = "spot"
        position = [0, 4, 0]
        direction = [0, -2, 0]
        outer_angle = 20
    )");
    const Light& a = s.lights[0];
    EXPECT_EQ(a.type, LightType::Spot);
    EXPECT_NEAR(glm::length(a.direction - dvec3(0.6, -0.8, 0.0)), 0.0, 1e-15);
    EXPECT_EQ(a.inner_angle_deg, 30.0);  // POV-Ray's radius and falloff
    EXPECT_EQ(a.outer_angle_deg, 45.0);
    EXPECT_EQ(a.tightness, 0.0);
    const Light& b = s.lights[1];
    EXPECT_EQ(b.direction, dvec3(0, -1, 0));
    EXPECT_FALSE(b.point_at);
    EXPECT_EQ(b.inner_angle_deg, 20.0);  // no wider than the cone it is in
}

TEST(LightKeys, AreaLightGivenByItsCornerIsCentred) {
    Scene s = scene_with(R"(
        [[light]]
        type = "area"
        corner = [-1, 6, -2]
        edge_u = [2, 0, 0]
        edge_v = [0, 0, 4]
        [[light]]
        type = "area"
        position = [0, 6, 0]
        edge_u = [2, 0, 0]
        edge_v = [0, 0, 4]
        samples = 8
        jitter = false
    )");
    EXPECT_EQ(s.lights[0].position, dvec3(0, 6, 0));
    EXPECT_EQ(s.lights[0].samples, 4);
    EXPECT_TRUE(s.lights[0].jitter);
    EXPECT_EQ(s.lights[1].position, dvec3(0, 6, 0));
    EXPECT_EQ(s.lights[1].samples, 8);
    EXPECT_FALSE(s.lights[1].jitter);
}

// An area light orbits as a whole (its edges keep their direction); a spot given point_at turns
// to keep aiming at it, one given a direction keeps that direction.
TEST(LightAnimation, EachLightTypeMovesAsAWhole) {
    Scene s = scene_with(R"(
        [animation]
        frames = 4
        [[animation.light_orbit]]
        light = "panel"
        [[animation.light_orbit]]
        light = "aimed"
        [[animation.light]]
        light = "fixed"
        keys = [{ time = 0, position = [0, 4, 0] }, { time = 1, position = [2, 4, 0] }]
        [[light]]
        name = "panel"
        type = "area"
        position = [3, 6, 0]
        edge_u = [1, 0, 0]
        edge_v = [0, 0, 1]
        [[light]]
        name = "aimed"
        type = "spot"
        position = [4, 5, 0]
        point_at = [0, 0, 0]
        [[light]]
        name = "fixed"
        type = "spot"
        position = [0, 4, 0]
        direction = [0, -1, 0]
    )");
    Scene half = scene_at(s, 0.5);
    const Light& panel = half.lights[0];
    EXPECT_NEAR(glm::length(panel.position - dvec3(-3, 6, 0)), 0.0, 1e-12);
    EXPECT_EQ(panel.edge_u, dvec3(1, 0, 0));
    const Light& aimed = half.lights[1];
    EXPECT_NEAR(glm::length(aimed.position - dvec3(-4, 5, 0)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(aimed.direction - glm::normalize(dvec3(4, -5, 0))), 0.0, 1e-12);
    const Light& fixed = half.lights[2];
    EXPECT_EQ(fixed.position, dvec3(1, 4, 0));
    EXPECT_EQ(fixed.direction, dvec3(0, -1, 0));
    // Frame 0 is the still scene, bit for bit.
    Scene start = scene_at(s, 0.0);
    EXPECT_EQ(start.lights[1].direction, s.lights[1].direction);
}

}  // namespace
}  // namespace lancer

// A POV-Ray user's words where lancer has others: the unknown key or type is still refused at
// its line and column, and the message names lancer's word. A near-typo of one of lancer's own
// keys keeps its did-you-mean.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "surface/expr/evaluate.hpp"

namespace lancer {
namespace {

const char* const kCamera = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n";

TEST(PovRayWords, KeysPovRayUsersWriteAreNamedInLancersTerms) {
    test::expect_scene_error(std::string(kCamera) + "[material.red]\ncolor = [1, 0, 0]\nphong = 0.5\n", 6, 1,
                             "unknown key 'phong' (POV-Ray's phong is lancer's specular, and its phong_size is shininess)");
    test::expect_scene_error("[camera]\neye = [0, 0, -5]\nlocation = [0, 0, -5]\nlook_at = [0, 0, 0]\n", 3, 1,
                             "POV-Ray's location is lancer's eye in [camera], position in [[light]]");
    test::expect_scene_error(std::string(kCamera) + "[[light]]\nposition = [0, 1, 0]\nangle = 60\n", 6, 1,
                             "POV-Ray's horizontal camera angle is [camera] angle");
    test::expect_scene_error(std::string(kCamera) + "[material.glass]\nfilter = 0.9\n", 5, 1,
                             "transmission = [f r, f g, f b]");
    test::expect_scene_error(std::string(kCamera) + "[[object]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\n"
                                                    "translate = [1, 0, 0]\n",
                             8, 1, "transform = [{ translate = [x, y, z] }, ...]");
}

TEST(PovRayWords, ObjectTypesPovRayUsersWriteAreNamedInLancersTerms) {
    test::expect_scene_error(std::string(kCamera) + "[[object]]\ntype = \"union\"\n", 5, 8, "POV-Ray's union is lancer's group");
    test::expect_scene_error(std::string(kCamera) + "[[object]]\ntype = \"quartic\"\n", 5, 8,
                             "lancer's implicit surfaces: type = \"implicit\"");
    test::expect_scene_error(std::string(kCamera) + "[[object]]\ntype = \"mesh2\"\n", 5, 8, "type = \"mesh\" with an OBJ or PLY file");
}

// POV-Ray's camera angle is horizontal: lancer's vertical fov for the scene's shape.
TEST(PovRayWords, TheCamerasAngleIsHorizontal) {
    const Scene s = test::scene_from_text("[render]\nwidth = 400\nheight = 200\n[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\nangle = 90\n");
    EXPECT_NEAR(s.camera.fov_deg, 2.0 * std::atan(0.5) * 180.0 / M_PI, 1e-12);  // 53.13 degrees
    test::expect_scene_error(std::string(kCamera) + "angle = 90\nfov = 40\n", 4, 9, "give either fov (vertical, lancer's) or angle");
    test::expect_scene_error(std::string(kCamera) + "angle = 180\n", 4, 9, "angle must be between 0 and 180 degrees");
}

TEST(PovRayWords, ANearTypoKeepsItsDidYouMean) {
    test::expect_scene_error(std::string(kCamera) + "[material.red]\ncolor = [1, 0, 0]\nspecularr = 0.5\n", 6, 1,
                             "did you mean 'specular'");
}

// POV-Ray's quartic as an implicit surface's `poly`: shapesq.inc's hyperbolic torus, whose
// comment gives its equation, coefficient for coefficient in POV-Ray's order.
TEST(PovRayWords, PolyCoefficientsInPovRaysOrderAreTheSurfacesFunction) {
    const Scene scene = test::scene_from_text(std::string(kCamera) + R"toml(
[[object]]
type = "implicit"
poly = [1, 0, 0, 0, 2, 0, 0, -2, 0, -104,
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
        1, 0, 0, -2, 0, 56, 0, 0, 0, 0,
        1, 0, 104, 0, 784]
box = { min = [-12, -12, -12], max = [12, 12, 12] }
)toml");
    const surface::ImplicitSurface& s = *std::get<ImplicitObject>(scene.objects.at(0).shape).surface;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-12.0, 12.0);
    for (int k = 0; k < 100; ++k) {
        const double x = u(rng), y = u(rng), z = u(rng);
        const double expected = x * x * x * x + 2 * x * x * y * y - 2 * x * x * z * z - 104 * x * x + y * y * y * y -
                                2 * y * y * z * z + 56 * y * y + z * z * z * z + 104 * z * z + 784;
        const double xyz[] = {x, y, z};
        EXPECT_NEAR(surface::evaluate<double>(s.f, xyz), expected, 1e-9 * (std::abs(expected) + 1e4));
    }
    ASSERT_TRUE(s.polynomial);
    EXPECT_EQ(s.polynomial->degree(), 4);
}

TEST(PovRayWords, PolyRefusesACountOfNoDegreeAndAFunctionBeside) {
    const std::string box = "box = { min = [-1, -1, -1], max = [1, 1, 1] }\n";
    test::expect_scene_error(std::string(kCamera) + "[[object]]\ntype = \"implicit\"\npoly = [1, 0, 0, 0, -1, 2]\n" + box, 6, 8,
                             "poly holds 6 coefficients; POV-Ray's poly of degree N has (N + 1)(N + 2)(N + 3) / 6");
    test::expect_scene_error(std::string(kCamera) + "[[object]]\ntype = \"implicit\"\nfunction = \"x\"\npoly = [1, 0, 0, -1]\n" + box,
                             7, 8, "give either function or poly");
    test::expect_scene_error(std::string(kCamera) + "[[object]]\ntype = \"implicit\"\npoly = [0, 0, 0, 0]\n" + box, 6, 8,
                             "every coefficient is 0");
    // A coefficient that is not a number is named by its own index (the index was once read in
    // the same call that advanced it, in an order C++ leaves open).
    test::expect_scene_error(std::string(kCamera) + "[[object]]\ntype = \"implicit\"\npoly = [1, 0, true, 0]\n" + box, 6,
                             15, "poly[2] must be a number or an expression (a string), not a boolean");
}

}  // namespace
}  // namespace lancer

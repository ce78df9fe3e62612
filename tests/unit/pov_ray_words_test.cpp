// A POV-Ray user's words where lancer has others: the unknown key or type is still refused at
// its line and column, and the message names lancer's word. A near-typo of one of lancer's own
// keys keeps its did-you-mean.
#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace lancer {
namespace {

const char* const kCamera = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n";

TEST(PovRayWords, KeysPovRayUsersWriteAreNamedInLancersTerms) {
    test::expect_scene_error(std::string(kCamera) + "[material.red]\ncolor = [1, 0, 0]\nphong = 0.5\n", 6, 1,
                             "unknown key 'phong' (POV-Ray's phong is lancer's specular, and its phong_size is shininess)");
    test::expect_scene_error("[camera]\neye = [0, 0, -5]\nlocation = [0, 0, -5]\nlook_at = [0, 0, 0]\n", 3, 1,
                             "POV-Ray's location is lancer's eye in [camera], position in [[light]]");
    test::expect_scene_error(std::string(kCamera) + "angle = 60\n", 4, 1,
                             "fov = 2 atan(tan(angle / 2) height / width)");
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

TEST(PovRayWords, ANearTypoKeepsItsDidYouMean) {
    test::expect_scene_error(std::string(kCamera) + "[material.red]\ncolor = [1, 0, 0]\nspecularr = 0.5\n", 6, 1,
                             "did you mean 'specular'");
}

}  // namespace
}  // namespace lancer

// Which scenes the GPU's packer gives a BVH (gpu/packing/acceleration_plan.cpp): sixteen bounded
// primitives, or two costly, tightly boxed shapes (a cheap one placed in its own coordinates among
// them), each of which every ray would otherwise test whole. That the pictures are the same either way is bvh_equivalence_test's (every scene against
// brute force).
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "gpu/packing/scene_packing.hpp"
#include "render/packing_scenes.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

bool gets_a_bvh(const std::string& objects) {
    return gpu::pack_scene(test::scene_from_text(test::kPackingCameraAndMaterial + objects)).features.has_bvh;
}

std::string prism(double x) {
    return fmt::format("[[object]]\ntype = \"prism\"\nheight1 = 0\nheight2 = 0.5\npoints = [[{0}, 0], [{1}, 0], [{0}, 1], [{0}, 0]]\n"
                       "material = \"m\"\n",
                       x, x + 1);
}
std::string lathe(double x) {
    return fmt::format("[[object]]\ntype = \"lathe\"\npoints = [[0, 0], [0.5, 0], [0.4, 1], [0, 1]]\nmaterial = \"m\"\n"
                       "transform = {{ translate = [{}, 0, 0] }}\n",
                       x);
}
std::string torus(double x) {
    return fmt::format("[[object]]\ntype = \"torus\"\ncenter = [{}, 0, 0]\nmajor_radius = 0.5\nminor_radius = 0.2\nmaterial = \"m\"\n", x);
}
std::string box(double x, const std::string& transform) {
    return fmt::format("[[object]]\ntype = \"box\"\nmin = [{}, 0, 0]\nmax = [{}, 1, 1]\nmaterial = \"m\"\n{}", x, x + 1,
                       transform);
}
std::string spheres(int count) {
    std::string text;
    for (int i = 0; i < count; ++i) text += test::sphere_object(1.5 * i, 0, 0.5);
    return text;
}

TEST(BvhChoice, SixteenBoundedPrimitivesOrTwoCostlyTightlyBoxedShapes) {
    EXPECT_FALSE(gets_a_bvh(spheres(15)));
    EXPECT_TRUE(gets_a_bvh(spheres(16)));
    EXPECT_TRUE(gets_a_bvh(prism(0) + prism(2))) << "two prisms";
    EXPECT_TRUE(gets_a_bvh(prism(0) + lathe(3))) << "a prism and a lathe";
    EXPECT_FALSE(gets_a_bvh(prism(0) + spheres(3))) << "one costly shape";
    EXPECT_FALSE(gets_a_bvh(torus(0) + torus(2) + torus(4))) << "tori ran no faster in a tree";
    const std::string turned = "transform = { rotate = [0, 30, 0] }\n";
    EXPECT_TRUE(gets_a_bvh(box(0, turned) + box(2, turned))) << "two boxes tested in their own coordinates";
    EXPECT_FALSE(gets_a_bvh(box(0, "") + box(2, "") + box(4, ""))) << "boxes in the world's";
}

}  // namespace
}  // namespace lancer

// Which scenes the GPU's packer gives a BVH (gpu/packing/acceleration_plan.cpp): sixteen bounded
// primitives, or two costly, tightly boxed shapes (a cheap one placed in its own coordinates among
// them), each of which every ray would otherwise test whole. That the pictures are the same either way is bvh_equivalence_test's (every scene against
// brute force).
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
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

// A lattice of count small spheres over a plane, in view.
std::string lattice(int count) {
    std::string text = "[render]\nwidth = 64\nheight = 36\nsamples = 1\n[camera]\neye = [11, 30, -30]\nlook_at = [11, 8, 11]\n"
                       "[[light]]\nposition = [40, 60, -30]\n[material.m]\ncolor = [0.8, 0.4, 0.2]\nspecular = 0.5\n"
                       "[[object]]\ntype = \"plane\"\nnormal = [0, 1, 0]\npoint = [0, -1, 0]\nmaterial = \"m\"\n";
    for (int i = 0; i < count; ++i)
        text += fmt::format("[[object]]\ntype = \"sphere\"\ncenter = [{}, {}, {}]\nradius = 0.35\nmaterial = \"m\"\n", i % 22,
                            i / 22 % 22, i / 484);
    return text;
}

// From 10,000 cheap shapes the tree's leaves hold up to four (accel/bvh.hpp's tree_options), on
// the GPU's packer and in the CPU reference alike: a third of the nodes, and the same picture as
// brute force and as the other backend.
TEST(BvhChoice, TenThousandCheapShapesTakeLeavesOfUpToFour) {
    const auto leaves = [](const gpu::PackedScene& packed, std::size_t& largest) {
        std::size_t count = 0;
        largest = 0;
        for (const gpu::BvhNode& n : packed.nodes)
            if (n.count > 0) {
                ++count;
                largest = std::max<std::size_t>(largest, n.count);
            }
        return count;
    };
    std::size_t largest = 0;
    const std::size_t single = leaves(gpu::pack_scene(test::scene_from_text(lattice(kManyCheapPrimitives - 1))), largest);
    EXPECT_GT(single, (kManyCheapPrimitives - 1) * 3 / 4) << "a few thousand shapes keep (mostly) single leaves";
    const Scene scene = test::scene_from_text(lattice(kManyCheapPrimitives));
    const std::size_t many = leaves(gpu::pack_scene(scene), largest);
    EXPECT_LT(many, kManyCheapPrimitives / 2);
    EXPECT_LE(largest, 4u);

    const Rgb8Image cpu = to_srgb8(CpuRenderer(0, Acceleration::Bvh).render(scene, {}));
    EXPECT_EQ(cpu.bytes, to_srgb8(CpuRenderer(0, Acceleration::BruteForce).render(scene, {})).bytes);
    test::expect_same_picture("lattice_of_ten_thousand", to_srgb8(test::render_on(test::Backend::Gpu, scene)), cpu);
}

}  // namespace
}  // namespace lancer

// The primitives outside the BVH reach the GPU sorted by shape family, with the frame saying
// where each family ends: shaders/scene.glsl tests each family in a loop of its own, so a
// primitive outside its family's range would never be tested. Beside expensive shapes in a BVH,
// a few analytic ones stay outside it. (That the pictures do not depend on the order is the
// image tests' business: ties go by a stable key.)
#include <array>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "gpu/packing/scene_packing.hpp"
#include "render/packing_scenes.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

using test::kPackingCameraAndMaterial;

// A rectangle under the objects.
const std::string kFloorRectangle = test::floor_rectangle(3);

const std::string kMixed = kPackingCameraAndMaterial + R"(
    [[object]]
    type = "sphere"
    center = [0, 0, 0]
    radius = 1
    material = "m"
)" + kFloorRectangle + R"(
    [[object]]
    type = "sphere"
    center = [2, 0, 0]
    radius = 0.5
    material = "m"
    [[object]]
    type = "box"
    min = [-2, -1, 1]
    max = [-1, 0, 2]
    material = "m"
    [[object]]
    type = "plane"
    point = [0, -2, 0]
    normal = [0, 1, 0]
    material = "m"
    [[object]]
    type = "sphere"
    center = [-2, 0, 0]
    radius = 0.5
    material = "m"
)";

TEST(FamilyOrder, PrimitivesOutsideTheBvhAreSortedByFamilyWithTheirEnds) {
    const Scene scene = test::scene_from_text(kMixed);
    const gpu::PackedScene packed = gpu::pack_scene(scene);
    ASSERT_TRUE(packed.nodes.empty()) << "six primitives: no BVH";
    const gpu::FrameParams frame = gpu::pack_frame(scene, packed);
    ASSERT_EQ(frame.unbounded_count, 6u);
    ASSERT_EQ(frame.primitive_count, 6u);
    // 3 spheres, a plane, a rectangle, a box; every later family is empty and ends at 6.
    std::array<uint, SHAPE_COUNT> expected_ends;
    expected_ends.fill(6);
    expected_ends[SHAPE_SPHERE] = 3;
    expected_ends[SHAPE_PLANE] = 4;
    expected_ends[SHAPE_RECTANGLE] = 5;
    static_assert(SHAPE_SPHERE == 0 && SHAPE_PLANE == 1 && SHAPE_RECTANGLE == 2 && SHAPE_BOX == 3);
    uint begin = frame.primitive_count - frame.unbounded_count;
    for (uint type = 0; type < SHAPE_COUNT; ++type) {
        const uint end = gpu::per_shape(frame.family_end, type);
        EXPECT_EQ(end, expected_ends[type]) << shape_name(type);
        for (uint i = begin; i < end; ++i) EXPECT_EQ(packed.primitives[i].type, type) << "primitive " << i;
        begin = end;
    }
    EXPECT_EQ(begin, frame.primitive_count);
    // Within a family, the scene's order (the sort is stable): spheres from objects 0, 2, 5.
    EXPECT_EQ(packed.primitives[0].object, 0u);
    EXPECT_EQ(packed.primitives[1].object, 2u);
    EXPECT_EQ(packed.primitives[2].object, 5u);
}

// A small sphere object centred at (x, y, 0).
std::string small_sphere(int x, int y) { return test::sphere_object(x, y, 0.2); }

// A bicubic patch (16 leaves with subdivision 2), and `spheres` small spheres beside it.
std::string patch_and_spheres(int spheres) {
    std::string text = kPackingCameraAndMaterial + kFloorRectangle + R"(
    [[object]]
    type = "bezier"
    subdivision = 2
    material = "m"
    control_points = [)";
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) text += fmt::format("{}[{}, {}, {}]", i + j == 0 ? "" : ", ", i, j, (i % 3) * (j % 3));
    text += "]\n";
    for (int k = 0; k < spheres; ++k)
        text += small_sphere(k, 2);
    return text;
}

// Types of the primitives in the BVH (the first ones) and outside it.
std::pair<std::string, std::string> where(const gpu::PackedScene& packed) {
    std::string inside, outside;
    const std::size_t in_bvh = packed.primitives.size() - packed.unbounded_count;
    for (std::size_t i = 0; i < packed.primitives.size(); ++i) (i < in_bvh ? inside : outside) += char('0' + packed.primitives[i].type);
    return {inside, outside};
}

// Beside Bezier leaves in a BVH, a few analytic shapes stay outside it, so that the leaves'
// tests do not run their code (BVH_HAS_ANALYTIC off); many of them go in as usual.
TEST(FamilyOrder, FewAnalyticShapesStayOutsideABvhOfPatches) {
    const gpu::PackedScene few = gpu::pack_scene(test::scene_from_text(patch_and_spheres(2)));
    ASSERT_FALSE(few.nodes.empty());
    EXPECT_FALSE(few.features.bvh_has_analytic);
    EXPECT_EQ(where(few).first, std::string(16, '0' + gpu::SHAPE_BEZIER));
    EXPECT_EQ(where(few).second, "002");  // two spheres, then the rectangle

    const gpu::PackedScene many = gpu::pack_scene(test::scene_from_text(patch_and_spheres(9)));
    EXPECT_TRUE(many.features.bvh_has_analytic);
    EXPECT_EQ(where(many).second, "");
    EXPECT_EQ(where(many).first.size(), 16u + 9u + 1u);
}

// Without expensive shapes, everything bounded is in the BVH.
TEST(FamilyOrder, AnalyticShapesAloneAreAllInTheBvh) {
    std::string text = kPackingCameraAndMaterial;
    for (int k = 0; k < 20; ++k)
        text += small_sphere(k, 0);
    text += "[[object]]\ntype = \"plane\"\nnormal = [0, 1, 0]\nmaterial = \"m\"\n";
    const gpu::PackedScene packed = gpu::pack_scene(test::scene_from_text(text));
    EXPECT_TRUE(packed.features.bvh_has_analytic);
    EXPECT_EQ(where(packed).first, std::string(20, '0' + gpu::SHAPE_SPHERE));
    EXPECT_EQ(where(packed).second, "1");  // the plane
}

}  // namespace
}  // namespace lancer

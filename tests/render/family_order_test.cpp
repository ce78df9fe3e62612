// The primitives outside the BVH reach the GPU sorted by shape family, with the frame saying
// where each family ends: shaders/scene.glsl tests each family in a loop of its own, so a
// primitive outside its family's range would never be tested. (That the pictures do not depend
// on the order is the image tests' business: ties go by a stable key.)
#include <string>

#include <gtest/gtest.h>

#include "gpu/scene_packing.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

const char* kMixed = R"(
    [camera]
    eye = [0, 1, -6]
    look_at = [0, 0, 0]
    [material.m]
    color = [0.8, 0.5, 0.2]
    [[object]]
    type = "sphere"
    center = [0, 0, 0]
    radius = 1
    material = "m"
    [[object]]
    type = "rectangle"
    corner = [-3, -1, -3]
    edge_u = [6, 0, 0]
    edge_v = [0, 0, 6]
    material = "m"
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
    const uint ends[] = {frame.sphere_end, frame.plane_end, frame.rectangle_end, frame.box_end,
                         frame.bezier_end, frame.parametric_end, frame.primitive_count};
    const uint expected_ends[] = {3, 4, 5, 6, 6, 6, 6};  // 3 spheres, a plane, a rectangle, a box
    uint begin = frame.primitive_count - frame.unbounded_count;
    for (uint type = 0; type < std::size(ends); ++type) {
        EXPECT_EQ(ends[type], expected_ends[type]) << "type " << type;
        for (uint i = begin; i < ends[type]; ++i) EXPECT_EQ(packed.primitives[i].type, type) << "primitive " << i;
        begin = ends[type];
    }
    // Within a family, the scene's order (the sort is stable): spheres from objects 0, 2, 5.
    EXPECT_EQ(packed.primitives[0].object, 0u);
    EXPECT_EQ(packed.primitives[1].object, 2u);
    EXPECT_EQ(packed.primitives[2].object, 5u);
}

}  // namespace
}  // namespace lancer

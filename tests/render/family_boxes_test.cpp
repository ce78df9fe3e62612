// The boxes around the families of analytic shapes outside the BVH (gpu/packing/family_boxes.hpp): a ray
// that misses one skips that family's loop or half of it, so a box must hold every member's
// float bounds (one ulp short would lose silhouettes), and it is given only where it pays. That
// the pictures do not change is the image tests' business (bvh_equivalence_test renders every
// scene by brute force, its families boxed, against the BVH, byte for byte).
#include <string>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "gpu/packing/scene_packing.hpp"
#include "render/packing_scenes.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

using test::kPackingCameraAndMaterial;
using test::sphere_object;

// A rectangle under the objects, so that the scene's box is larger than theirs.
const std::string kWideFloor = test::floor_rectangle(8);

// Every member of the family in [first, end) lies inside the packed box `half` (strictly: the
// box is rounded outward and padded like the BVH's).
void expect_holds(const gpu::PackedScene& packed, const gpu::FrameParams& frame, uint half, uint first, uint end) {
    const gpu::vec4 lo = frame.family_lo[half], hi = frame.family_hi[half];
    for (uint i = first; i < end; ++i) {
        const gpu::vec4 s = packed.primitives[i].p0;  // (centre, radius) as the shader reads them
        for (int k = 0; k < 3; ++k) {
            EXPECT_LT(lo[k], double(s[k]) - double(s.w)) << "sphere " << i << " axis " << k;
            EXPECT_GT(hi[k], double(s[k]) + double(s.w)) << "sphere " << i << " axis " << k;
        }
    }
}

TEST(FamilyBoxes, ThreeSpheresGetOneBoxThatHoldsThem) {
    const Scene scene = test::scene_from_text(kPackingCameraAndMaterial + kWideFloor + sphere_object(-2, 0, 0.5) + sphere_object(0, 0, 1) + sphere_object(2, 0, 0.5));
    const gpu::PackedScene packed = gpu::pack_scene(scene);
    EXPECT_TRUE(packed.features.family_boxed(gpu::SHAPE_SPHERE));
    EXPECT_FALSE(packed.features.family_split(gpu::SHAPE_SPHERE)) << "fewer than five";
    EXPECT_FALSE(packed.features.family_boxed(gpu::SHAPE_RECTANGLE)) << "one rectangle";
    const gpu::FrameParams frame = gpu::pack_frame(scene, packed);
    expect_holds(packed, frame, 2 * gpu::SHAPE_SPHERE, 0, gpu::per_shape(frame.family_end, gpu::SHAPE_SPHERE));
    const gpu::vec4 lo = frame.family_lo[2 * gpu::SHAPE_SPHERE], hi = frame.family_hi[2 * gpu::SHAPE_SPHERE];
    EXPECT_NEAR(lo.x, -2.5, 1e-5);  // no larger than the spheres need, but for the BVH's padding
    EXPECT_NEAR(hi.y, 1.0, 1e-5);
    EXPECT_EQ(gpu::per_shape(frame.family_split, gpu::SHAPE_SPHERE), gpu::per_shape(frame.family_end, gpu::SHAPE_SPHERE)) << "unsplit: the first half is the whole family";
}

// Six spheres in two clusters: cut between them, each half's box around its own three.
TEST(FamilyBoxes, FiveOrMoreAreCutInTwoHalvesWithABoxEach) {
    std::string text = kPackingCameraAndMaterial + kWideFloor;
    for (double x : {4.0, -4.5, 5.0, -3.5, 4.5, -4.0}) text += sphere_object(x, 0, 0.3);
    const Scene scene = test::scene_from_text(text);
    const gpu::PackedScene packed = gpu::pack_scene(scene);
    ASSERT_TRUE(packed.features.family_boxed(gpu::SHAPE_SPHERE));
    ASSERT_TRUE(packed.features.family_split(gpu::SHAPE_SPHERE));
    const gpu::FrameParams frame = gpu::pack_frame(scene, packed);
    ASSERT_EQ(gpu::per_shape(frame.family_end, gpu::SHAPE_SPHERE), 6u);
    EXPECT_EQ(gpu::per_shape(frame.family_split, gpu::SHAPE_SPHERE), 3u);
    for (uint i = 0; i < 6; ++i) EXPECT_EQ(packed.primitives[i].p0.x < 0.0f, i < 3) << "sphere " << i;
    expect_holds(packed, frame, 2 * gpu::SHAPE_SPHERE, 0, 3);
    expect_holds(packed, frame, 2 * gpu::SHAPE_SPHERE + 1, 3, 6);
    EXPECT_LT(frame.family_hi[2 * gpu::SHAPE_SPHERE].x, 0.0f) << "the left half's box ends before the right's spheres";
    EXPECT_GT(frame.family_lo[2 * gpu::SHAPE_SPHERE + 1].x, 0.0f);
}

TEST(FamilyBoxes, NoBoxWhereItWouldNotPay) {
    // Two spheres: one box test more, and at most one sphere test less.
    const gpu::PackedScene two = gpu::pack_scene(test::scene_from_text(kPackingCameraAndMaterial + kWideFloor + sphere_object(-1, 0, 0.5) + sphere_object(1, 0, 0.5)));
    EXPECT_FALSE(two.features.family_boxed(gpu::SHAPE_SPHERE));
    // Spheres filling most of the scene: a ray that enters the scene's box enters theirs.
    const gpu::PackedScene spread =
        gpu::pack_scene(test::scene_from_text(kPackingCameraAndMaterial + sphere_object(-4, 0, 1) + sphere_object(0, 0, 1) + sphere_object(4, 0, 1)));
    EXPECT_FALSE(spread.features.family_boxed(gpu::SHAPE_SPHERE));
    // Walls around everything (the Cornell box): every ray is inside their box.
    std::string room = kPackingCameraAndMaterial + sphere_object(0, 0, 0.2);
    for (int k = 0; k < 3; ++k)
        room += fmt::format("[[object]]\ntype = \"rectangle\"\ncorner = [-2, {}, -2]\nedge_u = [4, 0, 0]\nedge_v = [0, 0, 4]\n"
                            "material = \"m\"\n",
                            k - 1);
    EXPECT_FALSE(gpu::pack_scene(test::scene_from_text(room)).features.family_boxed(gpu::SHAPE_RECTANGLE));
    // In a BVH (16 or more bounded shapes), nothing is outside it to box.
    std::string many = kPackingCameraAndMaterial;
    for (int k = 0; k < 20; ++k) many += sphere_object(k, 0, 0.2);
    const gpu::PackedScene bvh = gpu::pack_scene(test::scene_from_text(many));
    EXPECT_FALSE(bvh.nodes.empty());
    EXPECT_FALSE(bvh.features.family_boxed(gpu::SHAPE_SPHERE));
}

}  // namespace
}  // namespace lancer

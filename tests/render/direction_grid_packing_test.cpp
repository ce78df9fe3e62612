// Which scenes the packer gives direction grids (gpu/packing/direction_grids.hpp), and where it lets every
// ray take one (GRIDS_ONLY: the shader then has no BVH traversal at all, so a ray without a grid
// would be lost). The grids' own geometry is tested in tests/unit/direction_grids_test.cpp; that
// the pictures stay the same, here and in bvh_equivalence_test (every scene against brute force).
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include <gtest/gtest.h>

#include "gpu/packing/scene_packing.hpp"
#include "render/packing_scenes.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// 27 spheres above a checkered floor, lit by two point lights: `many` in small.
std::string lattice_scene(const std::string& floor_extra = "", const std::string& sphere_extra = "",
                          const std::string& lights = "") {
    std::string text = R"(
        [render]
        width = 160
        height = 90
        samples = 1
        [camera]
        eye = [0, 4, -9]
        look_at = [0, 1.5, 0]
    )";
    text += lights.empty() ? "[[light]]\nposition = [-6, 9, -7]\n[[light]]\nposition = [7, 5, -4]\ncolor = [0.3, 0.3, 0.3]\n" : lights;
    text += "[material.floor]\nchecker = { colors = [[0.9, 0.9, 0.9], [0.2, 0.2, 0.2]], size = 1.0 }\nreflection = 0.2\n" + floor_extra;
    text += "[material.ball]\ncolor = [0.8, 0.3, 0.2]\nspecular = 0.5\n" + sphere_extra;
    text += "[[object]]\ntype = \"plane\"\nnormal = [0, 1, 0]\nmaterial = \"floor\"\n";
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                text += fmt::format("[[object]]\ntype = \"sphere\"\ncenter = [{}, {}, {}]\nradius = 0.35\nmaterial = \"ball\"\n",
                                    1.2 * (i - 1), 0.5 + 1.1 * j, 1.2 * (k - 1));
    return text;
}

TEST(DirectionGridPacking, ALatticeOverAMirrorTakesGridsForEveryRay) {
    const Scene scene = test::scene_from_text(lattice_scene());
    const gpu::PackedScene packed = gpu::pack_scene(scene);
    ASSERT_TRUE(packed.features.has_bvh);
    EXPECT_TRUE(packed.features.direction_grids);
    EXPECT_TRUE(packed.features.grids_only);
    ASSERT_NE(packed.mirror_plane, gpu::NO_PRIMITIVE);
    EXPECT_EQ(packed.primitives[packed.mirror_plane].type, gpu::SHAPE_PLANE);
    EXPECT_EQ(gpu::pack_frame(scene, packed).mirror_plane, packed.mirror_plane);
    ASSERT_EQ(packed.grids.size(), gpu::DIRECTION_GRID_COUNT);
    for (uint k : {gpu::DIRECTION_GRID_EYE, gpu::DIRECTION_GRID_MIRROR, gpu::DIRECTION_GRID_LIGHT, gpu::DIRECTION_GRID_LIGHT + 1})
        EXPECT_EQ(packed.grids[k].valid, 1u) << "grid " << k;
    EXPECT_EQ(packed.grids[gpu::DIRECTION_GRID_LIGHT + 2].valid, 0u) << "no third light";
}

// The contract, broken on purpose: mirror balls reflect without a grid, and the pipeline is told
// that every ray takes one. Under the validation layer (tests) the render fails loudly instead of
// reading past the grids.
TEST(DirectionGridPacking, ARayWithoutAGridUnderGridsOnlyFailsTheRender) {
    const Scene scene = test::scene_from_text(lattice_scene("", "reflection = 0.5\n"));
    ASSERT_FALSE(gpu::pack_scene(scene).features.grids_only);
    GpuRenderer gpu(gpu::ContextOptions{"", true});
    gpu.override_features([](gpu::ShaderFeatures& f) { f.grids_only = true; });
    try {
        gpu.render(scene, {});
        FAIL() << "rendered with rays the pipeline cannot trace";
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("GRIDS_ONLY"), std::string::npos) << e.what();
    }
    gpu.override_features({});
    EXPECT_NO_THROW(gpu.render(scene, {}));
}

TEST(DirectionGridPacking, AnyRayWithoutAGridKeepsTheBvh) {
    struct Case {
        const char* why;
        std::string text;
    };
    const Case cases[] = {
        {"a reflecting sphere: its reflections start anywhere", lattice_scene("", "reflection = 0.3\n")},
        {"an area light: its shadow rays end anywhere on it",
         lattice_scene("", "", "[[light]]\ntype = \"area\"\nposition = [0, 9, -6]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]\n")},
        {"a light among the spheres", lattice_scene("", "", "[[light]]\nposition = [0.6, 1.0, 0.6]\n")},
        {"a bumpy mirror: its reflections are not a mirror image's",
         lattice_scene("bump = { type = \"noise\", amount = 0.3, scale = 0.5 }\n")},
    };
    for (const Case& c : cases) {
        const gpu::PackedScene packed = gpu::pack_scene(test::scene_from_text(c.text));
        EXPECT_TRUE(packed.features.direction_grids) << c.why;
        EXPECT_FALSE(packed.features.grids_only) << c.why;
    }
}

TEST(DirectionGridPacking, TransparencyAndFewPrimitivesHaveNoGrids) {
    const gpu::PackedScene glass = gpu::pack_scene(test::scene_from_text(lattice_scene("", "transmission = 0.8\nior = 1.5\n")));
    EXPECT_FALSE(glass.features.direction_grids) << "a shadow ray through glass needs every hit, in order";
    const gpu::PackedScene few = gpu::pack_scene(test::scene_from_text(test::kPackingCameraAndMaterial + test::sphere_object(0, 0, 1)));
    EXPECT_FALSE(few.features.has_bvh);
    EXPECT_FALSE(few.features.direction_grids);
    EXPECT_TRUE(few.grids.empty());
}

// With every ray through the grids, and with some through the BVH, the GPU draws what it draws by
// brute force, byte for byte: grids, mirror and lights together at a size where any lost
// primitive shows.
TEST(DirectionGridPacking, GridsRenderWhatBruteForceRenders) {
    GpuRenderer grids(gpu::ContextOptions{"", true}, Acceleration::BvhAlways);
    GpuRenderer brute(gpu::ContextOptions{"", true}, Acceleration::BruteForce);
    for (const std::string& text : {lattice_scene(), lattice_scene("", "reflection = 0.3\n")}) {
        const Scene scene = test::scene_from_text(text);
        Rgb8Image a = to_srgb8(grids.render(scene, {}));
        Rgb8Image b = to_srgb8(brute.render(scene, {}));
        ImageDiff d = compare_images(a, b, 0);
        EXPECT_EQ(d.max_abs, 0) << d.fraction_over * a.width * a.height << " pixels differ "
                                << test::save_comparison("direction-grids", a, b);
    }
}

}  // namespace
}  // namespace lancer

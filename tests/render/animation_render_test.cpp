// Animations as pictures: the orbit keeps its target centred and round, frame 0 is the still
// scene it claims to be, the GPU re-uploads only what changed (and never too little), and the
// backends agree half way through every shipped animation.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "gpu/layout.hpp"
#include "gpu/packing/primitive_packing.hpp"
#include "gpu/packing/scene_packing.hpp"
#include "mesh/mesh_geometry.hpp"
#include "scene/animation.hpp"
#include "scene/load_scene.hpp"
#include "support/test_meshes.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

using test::Backend;
using test::backend_name;


bool identical(const FloatImage& a, const FloatImage& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(a.pixels[0])) == 0;
}

// The shape of the pixels at least half covered by the target, to sub-pixel accuracy.
struct Silhouette {
    int width = 0, height = 0;     // bounding box, pixels
    double cx = 0, cy = 0;         // centroid, pixels from the top-left corner
    double var_x = 0, var_y = 0, cov_xy = 0;
    int pixels = 0;
};

Silhouette silhouette(const FloatImage& img) {
    Silhouette s;
    int x0 = img.width, x1 = -1, y0 = img.height, y1 = -1;
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            if (img.at(x, y).r < 0.5f) continue;  // flat red 1.0 on black: coverage >= 1/2
            double px = x + 0.5, py = y + 0.5;
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
            sx += px, sy += py, sxx += px * px, syy += py * py, sxy += px * py;
            ++s.pixels;
        }
    }
    if (s.pixels == 0) return s;
    s.width = x1 - x0 + 1;
    s.height = y1 - y0 + 1;
    s.cx = sx / s.pixels;
    s.cy = sy / s.pixels;
    s.var_x = sxx / s.pixels - s.cx * s.cx;
    s.var_y = syy / s.pixels - s.cy * s.cy;
    s.cov_xy = sxy / s.pixels - s.cx * s.cy;
    return s;
}

// A unit sphere at (1, 2, 3), flat red (ambient only), on black, circled at `height`. The field
// of view follows the distance so the sphere spans about 60% of the image height at every height.
Scene orbit_scene(double height) {
    double distance = std::hypot(6.0, height);
    double fov = 2.0 * std::atan(std::tan(std::asin(1.0 / distance)) / 0.6) * 180.0 / M_PI;
    return test::scene_from_text(fmt::format(R"(
        [render]
        width = 64
        height = 40
        samples = 4
        [animation]
        frames = 12
        cyclic = true
        [animation.camera_orbit]
        center = [1, 2, 3]
        radius = 6
        height = {}
        start_angle = 17
        [camera]
        eye = [0, 0, -10]
        look_at = [0, 0, 0]
        fov = {}
        [material.flat]
        color = [1, 0, 0]
        ambient = 1
        diffuse = 0
        [[object]]
        type = "sphere"
        center = [1, 2, 3]
        radius = 1
        material = "flat"
    )", height, fov));
}

class OrbitCorrectness : public testing::TestWithParam<std::tuple<Backend, double>> {};

// The issue's orbit test: at every frame the target is at the image centre and its silhouette
// is a circle (bounding box width = height within 1 px, isotropic second moments), whatever
// the orbit height. A sheared or non-orthogonal camera basis (the original project's bug)
// turns the disc into an ellipse; a wrong look-at moves it off centre.
TEST_P(OrbitCorrectness, TargetIsCentredAndRoundAtEveryFrame) {
    auto [backend, height] = GetParam();
    Scene scene = orbit_scene(height);
    const Animation& a = *scene.animation;
    for (int k = 0; k < a.frames; ++k) {
        SCOPED_TRACE(fmt::format("{} height {} frame {}", backend_name(backend), height, k));
        Scene frame = scene_at(scene, frame_time(a, k));
        FloatImage img = test::render_on(backend, frame);
        Silhouette s = silhouette(img);
        ASSERT_GT(s.pixels, 100) << "the target is not in the picture";
        EXPECT_LE(std::abs(s.width - s.height), 1) << s.width << "x" << s.height;
        EXPECT_GE(s.height, 22);  // ~60% of 40 px: the framing is what the test assumes
        EXPECT_NEAR(s.cx, img.width / 2.0, 0.25);
        EXPECT_NEAR(s.cy, img.height / 2.0, 0.25);
        EXPECT_NEAR(s.var_x / s.var_y, 1.0, 0.05);
        EXPECT_LT(std::abs(s.cov_xy) / s.var_x, 0.02);
    }
}

INSTANTIATE_TEST_SUITE_P(Heights, OrbitCorrectness,
                         testing::Combine(testing::Values(Backend::Gpu, Backend::Cpu),
                                          testing::Values(-5.0, 0.0, 2.0, 8.0, 30.0)),
                         [](const auto& info) {
                             double h = std::get<1>(info.param);
                             return std::string(backend_name(std::get<0>(info.param))) + "_height_" + (h < 0 ? "minus_" : "") +
                                    std::to_string(static_cast<int>(std::abs(h)));
                         });

// Frame 0 of an animation whose every track starts at values exact in binary, and the still
// scene written with those values by hand: bit-identical images on each backend.
const char* kAnimated = R"(
    [render]
    width = 48
    height = 27
    samples = 2
    [animation]
    frames = 8
    cyclic = true
    [animation.camera_orbit]
    center = [1, 1, 0.5]
    radius = 6
    height = 2
    start_angle = 0
    [[animation.light_orbit]]
    light = "sun"
    center = [0, 0, 0]
    radius = 5
    height = 8
    start_angle = 0
    [[animation.light]]
    light = 1
    interpolation = "smooth"
    keys = [{ time = 0, position = [-3, 6, -4], color = [0.5, 0.25, 0.75] },
            { time = 0.5, position = [3, 4, -4], color = [1, 1, 1] }]
    [[animation.object]]
    object = "ball"
    interpolation = "smooth"
    keys = [{ time = 0, translate = [0, 0, 0] }, { time = 0.5, translate = [0, 1.5, 0] }]
    [camera]
    eye = [0, 9, -20]      # not frame 0: the orbit places the camera
    look_at = [0, 0, 0]
    fov = 40
    [[light]]
    name = "sun"
    position = [9, 9, 9]   # not frame 0 either
    [[light]]
    position = [9, 9, 9]
    color = [0.1, 0.1, 0.1]
    [material.floor]
    checker = { colors = [[1, 1, 1], [0.3, 0.3, 0.3]] }
    [material.shiny]
    color = [0.2, 0.4, 0.9]
    specular = 0.6
    reflection = 0.3
    [[object]]
    type = "plane"
    normal = [0, 1, 0]
    material = "floor"
    [[object]]
    name = "ball"
    type = "sphere"
    center = [1, 1, 0.5]
    radius = 1
    material = "shiny"
)";

const char* kStill = R"(
    [render]
    width = 48
    height = 27
    samples = 2
    [camera]
    eye = [7, 3, 0.5]
    look_at = [1, 1, 0.5]
    fov = 40
    [[light]]
    position = [5, 8, 0]
    [[light]]
    position = [-3, 6, -4]
    color = [0.5, 0.25, 0.75]
    [material.floor]
    checker = { colors = [[1, 1, 1], [0.3, 0.3, 0.3]] }
    [material.shiny]
    color = [0.2, 0.4, 0.9]
    specular = 0.6
    reflection = 0.3
    [[object]]
    type = "plane"
    normal = [0, 1, 0]
    material = "floor"
    [[object]]
    type = "sphere"
    center = [1, 1, 0.5]
    radius = 1
    material = "shiny"
)";

class FrameZero : public testing::TestWithParam<Backend> {};

TEST_P(FrameZero, EqualsTheStillSceneBitForBit) {
    Scene animated = test::scene_from_text(kAnimated);
    Scene still = test::scene_from_text(kStill);
    FloatImage a = test::render_on(GetParam(), scene_at(animated, frame_time(*animated.animation, 0)));
    FloatImage b = test::render_on(GetParam(), still);
    if (!identical(a, b)) {
        std::string dir = test::save_comparison(std::string("frame-zero-") + backend_name(GetParam()), to_srgb8(a), to_srgb8(b));
        ADD_FAILURE() << "frame 0 differs from the still scene; images in " << dir;
    }
    // The animation does move: frame 1 is another picture.
    EXPECT_FALSE(identical(test::render_on(GetParam(), scene_at(animated, frame_time(*animated.animation, 1))), b));
}

INSTANTIATE_TEST_SUITE_P(Backends, FrameZero, testing::Values(Backend::Gpu, Backend::Cpu),
                         [](const auto& info) { return backend_name(info.param); });

// Camera-only frames write the frame uniform alone; a moved light adds its element of the light
// array; a moved object its primitive.
TEST(GpuUpload, WritesOnlyTheBuffersThatChanged) {
    Scene scene = test::scene_from_text(kStill);
    GpuRenderer& gpu = test::gpu_renderer();
    const std::size_t frame = sizeof(gpu::FrameParams);
    const std::size_t lights = scene.lights.size() * sizeof(gpu::Light);
    const std::size_t primitives = scene.objects.size() * sizeof(gpu::Primitive);
    const std::size_t materials = (scene.materials.size()) * sizeof(gpu::Material);

    gpu.render(scene, {});
    scene.camera.eye.x += 0.5;
    gpu.render(scene, {});
    EXPECT_EQ(gpu.last_upload().bytes_written, frame);
    EXPECT_EQ(gpu.last_upload().bytes_skipped, lights + primitives + materials);

    scene.lights[0].position.y += 1;
    gpu.render(scene, {});
    EXPECT_EQ(gpu.last_upload().bytes_written, frame + sizeof(gpu::Light));

    std::get<Sphere>(scene.objects[1].shape).center.y += 0.25;
    gpu.render(scene, {});
    EXPECT_EQ(gpu.last_upload().bytes_written, frame + sizeof(gpu::Primitive));
}

// A row of 21 small spheres over a mirror floor, lit by one point light: every ray can take a
// direction grid (GRIDS_ONLY); with `glass`, the middle sphere is transparent and rays go
// through the BVH instead.
std::string row_of_spheres(bool glass) {
    std::string text = R"(
        [render]
        width = 40
        height = 24
        samples = 1
        [camera]
        eye = [0, 3, -12]
        look_at = [0, 0, 0]
        fov = 50
        [[light]]
        position = [4, 9, -6]
        color = [1, 1, 1]
        [material.ball]
        color = [0.8, 0.3, 0.2]
        specular = 0.4
        [material.floor]
        color = [0.4, 0.4, 0.4]
        reflection = 0.5
        [[object]]
        type = "plane"
        point = [0, -0.3, 0]
        normal = [0, 1, 0]
        material = "floor"
    )";
    if (glass) text += "[material.glass]\ncolor = [1, 1, 1]\ntransmission = [0.9, 0.9, 0.9]\nior = 1.5\n";
    for (int i = -10; i <= 10; ++i)
        text += fmt::format("[[object]]\ntype = \"sphere\"\ncenter = [{}, 0, 0]\nradius = 0.3\nmaterial = \"{}\"\n", i,
                            glass && i == 0 ? "glass" : "ball");
    return text;
}

// A frame that moves only the camera writes the frame uniform and the view's direction grids,
// nothing of the scene's, and keeps its pipeline: the pipeline's constants are per scene. The
// second camera stands in the row, beside 21 spheres at once, where a grid would list too much
// for speed: where every ray takes a grid, the view's grids are built anyway, never the BVH.
TEST(GpuUpload, ACameraMoveWritesOnlyTheViewAndKeepsThePipeline) {
    for (bool glass : {false, true}) {
        Scene scene = test::scene_from_text(row_of_spheres(glass));
        GpuRenderer gpu(gpu::ContextOptions{"", true});
        const gpu::PackedScene first = gpu::pack_scene(scene);
        ASSERT_TRUE(first.features.has_bvh);
        ASSERT_EQ(first.features.grids_only, !glass);
        gpu.render(scene, {});
        const std::size_t pipelines = gpu.pipelines_built();
        for (const dvec3 eye : {dvec3(2, 5, -9), dvec3(0.2, 0, 0.1), dvec3(-3, 1, -4)}) {
            scene.camera.eye = eye;
            const FloatImage image = gpu.render(scene, {});
            const gpu::PackedScene packed = gpu::pack_scene(scene);
            const std::size_t view = 2 * sizeof(gpu::DirectionGrid) + 4 * (packed.view_grid_cells + packed.view_grid_entries);
            EXPECT_GT(gpu.last_upload().bytes_written, sizeof(gpu::FrameParams) - 1);
            EXPECT_LE(gpu.last_upload().bytes_written, sizeof(gpu::FrameParams) + (glass ? 0 : view)) << "eye " << eye.x;
            EXPECT_EQ(gpu.pipelines_built(), pipelines) << "eye " << eye.x << ": a camera move built a pipeline";
            EXPECT_EQ(packed.features, first.features);
            GpuRenderer bvh_alone(gpu::ContextOptions{"", true});
            bvh_alone.set_grid_use(gpu::GridUse::Never);
            EXPECT_TRUE(identical(image, bvh_alone.render(scene, {}))) << "eye " << eye.x << ": grids and the BVH disagree";
        }
    }
}

// kStill with 20 small spheres more, enough bounded objects for the GPU to use its BVH, at 32x18.
Scene still_with_twenty_spheres() {
    std::string text = std::string(kStill);
    for (int i = 0; i < 20; ++i)
        text += fmt::format("[[object]]\ntype = \"sphere\"\ncenter = [{}, 0.2, 2]\nradius = 0.15\n", -2.0 + 0.2 * i);
    Scene scene = test::scene_from_text(text);
    scene.render.width = 32;
    scene.render.height = 18;
    return scene;
}

// Frames that move only the camera and lights reuse the BVH; moving an object builds it again,
// and the picture is then exactly that of a fresh renderer (no stale tree), on both backends.
TEST(BvhReuse, StaticGeometryIsNotBuiltAgainFrameAfterFrame) {
    Scene scene = still_with_twenty_spheres();
    GpuRenderer gpu(gpu::ContextOptions{"", true});
    CpuRenderer cpu;
    auto builds = [&] { return std::pair{gpu.bvh_builds(), cpu.bvh_builds()}; };
    auto render_both = [&](const Scene& s) { return std::pair{gpu.render(s, {}), cpu.render(s, {})}; };

    render_both(scene);
    EXPECT_EQ(builds(), std::pair(std::size_t{1}, std::size_t{1}));
    scene.camera.eye.x += 0.5;
    scene.lights[0].position.y += 1;
    render_both(scene);
    EXPECT_EQ(builds(), std::pair(std::size_t{1}, std::size_t{1})) << "camera and lights moved, geometry did not";

    std::get<Sphere>(scene.objects.back().shape).center.y += 0.3;
    auto [g, c] = render_both(scene);
    EXPECT_EQ(builds(), std::pair(std::size_t{2}, std::size_t{2})) << "an object moved";
    GpuRenderer fresh_gpu(gpu::ContextOptions{"", true});
    EXPECT_TRUE(identical(g, fresh_gpu.render(scene, {})));
    EXPECT_TRUE(identical(c, CpuRenderer().render(scene, {})));
}

// A renderer told it renders one still (lancer render) keeps no tree and, on the GPU, frees the
// host's packed arrays as it uploads them: the same pictures as any renderer's; and should it
// render again, a moved object included, nothing stale is left (the next upload writes every array).
TEST(BvhReuse, ARendererForOneStillKeepsNoTreeAndRendersTheSame) {
    Scene scene = still_with_twenty_spheres();
    GpuRenderer gpu(gpu::ContextOptions{"", true});
    CpuRenderer cpu;
    gpu.expect_one_still();
    cpu.expect_one_still();
    for (int round = 0; round < 2; ++round) {
        const FloatImage g = gpu.render(scene, {}), c = cpu.render(scene, {});
        EXPECT_EQ(gpu.bvh_builds(), 0u);
        EXPECT_EQ(cpu.bvh_builds(), 0u);
        EXPECT_TRUE(identical(g, GpuRenderer(gpu::ContextOptions{"", true}).render(scene, {}))) << "round " << round;
        EXPECT_TRUE(identical(c, CpuRenderer().render(scene, {}))) << "round " << round;
        std::get<Sphere>(scene.objects.back().shape).center.y += 0.3;
    }
    // Adaptive anti-aliasing traces in steps: the CPU's share one tree.
    scene.render.aa_threshold = 0.1;
    cpu.render(scene, {});
    EXPECT_EQ(cpu.bvh_builds(), 1u);
}

// kStill with its sphere made a mesh (an icosphere), and a sphere set of two beside it.
Scene still_with_a_mesh_and_a_sphere_set() {
    Scene scene = test::scene_from_text(kStill);
    scene.objects.push_back(scene.objects[1]);
    Mesh mesh;
    mesh.geometry = std::make_shared<const MeshGeometry>(test::icosphere(2, dvec3(-0.8, 0.6, 1.0), 0.6));
    scene.objects[1].shape = mesh;
    SphereSet set;
    set.cloud = std::make_shared<const SphereCloud>(std::vector<glm::vec4>{{0.9f, 0.3f, 0.8f, 0.3f}, {1.4f, 0.25f, 1.2f, 0.25f}},
                                                    std::vector<std::uint32_t>{}, std::vector<dvec3>{});
    scene.objects[2].shape = set;
    for (int k : {1, 2}) scene.objects[k].placement = Placement{glm::dmat4(1.0), glm::dmat4(1.0), true};
    return scene;
}

// The packer gives out the features before it builds the meshes' and sphere sets' trees, so that
// the renderer's pipeline builds meanwhile: at the call no tree is built, after it both are, and
// the features given are the packed scene's.
TEST(BvhReuse, ThePackerGivesTheFeaturesBeforeItBuildsTheSetsTrees) {
    const Scene scene = still_with_a_mesh_and_a_sphere_set();
    ElementTreeCache trees;
    std::optional<gpu::ShaderFeatures> given;
    std::size_t builds_then = 99;
    gpu::PackOptions options;
    options.element_trees = &trees;
    options.on_features = [&](const gpu::ShaderFeatures& f) {
        ASSERT_FALSE(given) << "given twice";
        given = f;
        builds_then = trees.builds();
    };
    const gpu::PackedScene packed = gpu::pack_scene(scene, options);
    ASSERT_TRUE(given);
    EXPECT_EQ(builds_then, 0u);
    EXPECT_EQ(trees.builds(), 2u);
    EXPECT_TRUE(*given == packed.features);
    EXPECT_TRUE(packed.features.has_shape(SHAPE_MESH) && packed.features.has_shape(SHAPE_SPHERES));
    EXPECT_FALSE(packed.mesh_triangles.empty());
    EXPECT_EQ(packed.set_spheres.size(), 2u);
}

// lancer render's one still: the GPU path frees the scene's objects once it has packed them
// (render_once) and draws the picture of a renderer that keeps them; it keeps them where it was
// not told of one still, or packs for more than one step (adaptive anti-aliasing).
TEST(OneStill, RenderOnceFreesTheObjectsAndDrawsTheSame) {
    const Scene scene = still_with_a_mesh_and_a_sphere_set();  // placed objects, a mesh and a set
    const FloatImage kept = GpuRenderer(gpu::ContextOptions{"", true}).render(scene, {});

    GpuRenderer one_still(gpu::ContextOptions{"", true});
    one_still.expect_one_still();
    Scene given = scene;
    EXPECT_TRUE(identical(one_still.render_once(given, {}), kept));
    EXPECT_TRUE(given.objects.empty());
    EXPECT_EQ(given.render.width, scene.render.width) << "only the objects go";

    Scene for_frames = scene;
    EXPECT_TRUE(identical(GpuRenderer(gpu::ContextOptions{"", true}).render_once(for_frames, {}), kept));
    EXPECT_EQ(for_frames.objects.size(), scene.objects.size());

    Scene adaptive = scene;
    adaptive.render.aa_threshold = 0.1;
    GpuRenderer adaptive_still(gpu::ContextOptions{"", true});
    adaptive_still.expect_one_still();
    const FloatImage stepped = adaptive_still.render_once(adaptive, {});
    EXPECT_EQ(adaptive.objects.size(), scene.objects.size());
    EXPECT_TRUE(identical(stepped, GpuRenderer(gpu::ContextOptions{"", true}).render(adaptive, {})));
}

// A still of cheap unplaced shapes only is packed from its last object back, each freed as it is
// packed (pack_scene): the same picture, near the origin and far from it (where the packer
// works on a rebased copy of the scene).
TEST(OneStill, CheapShapesArePackedFromTheBackAndDrawTheSame) {
    for (const double offset : {0.0, 2e5}) {
        Scene scene = test::scene_from_text(kStill);
        for (int k = 0; k < 6; ++k) {
            Object o = scene.objects.back();
            o.shape = k % 3 == 0 ? Shape(Sphere{dvec3(-1.2 + 0.5 * k, 0.3, 1.5), 0.25})
                      : k % 3 == 1 ? Shape(Box{dvec3(-1.3 + 0.5 * k, 0.1, 0.8), dvec3(-1.1 + 0.5 * k, 0.4, 1.0)})
                                   : Shape(Torus{dvec3(-1.2 + 0.5 * k, 0.3, 2.2), dvec3(0, 1, 0), 0.2, 0.05});
            scene.objects.push_back(o);
        }
        scene = test::moved_scene(scene, {offset, 0.0, 0.0});
        for (const Object& o : scene.objects) ASSERT_TRUE(gpu::packs_alone(o));
        const FloatImage kept = GpuRenderer(gpu::ContextOptions{"", true}).render(scene, {});
        GpuRenderer one_still(gpu::ContextOptions{"", true});
        one_still.expect_one_still();
        Scene given = scene;
        EXPECT_TRUE(identical(one_still.render_once(given, {}), kept)) << "offset " << offset;
        EXPECT_TRUE(given.objects.empty());
    }
}

// A mesh's and a sphere set's trees are built once for frame after frame (the shared geometry
// names them), while their placements move; a new geometry gets its own tree, the old one's is let
// go, and every picture is a fresh renderer's. A renderer for one still keeps none.
TEST(BvhReuse, AMeshOrSphereSetTreeIsBuiltOnceForEveryFrame) {
    Scene scene = still_with_a_mesh_and_a_sphere_set();
    GpuRenderer gpu(gpu::ContextOptions{"", true});
    auto fresh = [&] { return GpuRenderer(gpu::ContextOptions{"", true}).render(scene, {}); };
    EXPECT_TRUE(identical(gpu.render(scene, {}), fresh()));
    EXPECT_EQ(gpu.element_tree_builds(), 2u);
    scene.camera.eye.x += 0.5;
    for (int k : {1, 2}) {
        const glm::dmat4 moved = glm::translate(glm::dmat4(1.0), dvec3(0.1 * k, 0.2, 0.0));
        scene.objects[k].placement = Placement{moved, glm::inverse(moved), true};
    }
    EXPECT_TRUE(identical(gpu.render(scene, {}), fresh())) << "camera and placements moved";
    EXPECT_EQ(gpu.element_tree_builds(), 2u) << "camera and placements moved, geometry did not";

    const std::weak_ptr<const MeshGeometry> old_geometry = std::get<Mesh>(scene.objects[1].shape).geometry;
    std::get<Mesh>(scene.objects[1].shape).geometry = std::make_shared<const MeshGeometry>(test::icosphere(1, dvec3(-0.7, 0.5, 1.0), 0.5));
    EXPECT_TRUE(identical(gpu.render(scene, {}), fresh())) << "a new mesh";
    EXPECT_EQ(gpu.element_tree_builds(), 3u) << "a new mesh";
    EXPECT_TRUE(old_geometry.expired()) << "the old mesh's tree is let go";

    GpuRenderer one_still(gpu::ContextOptions{"", true});
    one_still.expect_one_still();
    EXPECT_TRUE(identical(one_still.render(scene, {}), fresh()));
    EXPECT_EQ(one_still.element_tree_builds(), 0u);
}

// Skipping must never leave stale data: B after A equals B after B, and A really differs.
TEST(GpuUpload, AlternatingScenesRenderAsFreshOnes) {
    Scene a = test::scene_from_text(kStill);
    Scene b = a;
    std::get<Sphere>(b.objects[1].shape).center.x -= 0.5;
    b.lights[1].color = dvec3(0.9, 0.2, 0.2);
    b.materials[0].checker->size = 0.5;
    GpuRenderer& gpu = test::gpu_renderer();
    FloatImage b1 = gpu.render(b, {});
    FloatImage b2 = gpu.render(b, {});
    FloatImage a1 = gpu.render(a, {});
    FloatImage b3 = gpu.render(b, {});
    EXPECT_TRUE(identical(b1, b2));
    EXPECT_TRUE(identical(b1, b3));
    EXPECT_FALSE(identical(a1, b1));
    // Each change on its own must reach the GPU.
    for (int change = 0; change < 3; ++change) {
        Scene c = a;
        if (change == 0) std::get<Sphere>(c.objects[1].shape).center.x -= 0.5;
        if (change == 1) c.lights[1].color = dvec3(0.9, 0.2, 0.2);
        if (change == 2) c.materials[0].checker->size = 0.5;
        FloatImage before = gpu.render(a, {});
        EXPECT_FALSE(identical(gpu.render(c, {}), before)) << "change " << change;
    }
}

// Half way through each shipped animation the backends agree, with the metric and reduced size
// of backends_agree_test.cpp, so animated lights and cameras are covered, not only frame 0.
TEST(AnimatedScenes, BackendsAgreeMidAnimation) {
    int animated = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenes"))) {
        if (entry.path().extension() != ".toml") continue;
        Scene scene = load_scene(entry.path().string());
        if (!scene.animation) continue;
        ++animated;
        Scene frame = scene_at(scene, 0.37);
        int width = 240;
        frame.render.height = std::max(1, frame.render.height * width / frame.render.width);
        frame.render.width = width;
        Rgb8Image gpu = to_srgb8(test::gpu_renderer().render(frame, {}));
        Rgb8Image cpu = to_srgb8(CpuRenderer().render(frame, {}));
        test::expect_same_picture("animated-" + entry.path().stem().string() + "-at-0.37", gpu, cpu);
    }
    EXPECT_GE(animated, 2);
}

}  // namespace
}  // namespace lancer

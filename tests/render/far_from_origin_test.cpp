// A scene far from the world origin, camera and lights with it, renders on the GPU the picture it
// renders at the origin: everything the GPU sees is rebased near the camera, in double, before it
// is rounded to float (gpu/packing/float_anchor.hpp). Without that, float keeps about 0.06 of a unit at
// 10^6 and nothing at 10^9.
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "gpu/packing/float_anchor.hpp"
#include "gpu/packing/scene_packing.hpp"
#include "scene/animation.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// Every shape family the GPU packs with positions of its own, a solid checker (whose cells
// depend on world coordinates) and a shadow.
const char* kScene = R"toml(
    [render]
    width = 96
    height = 64
    samples = 2
    [camera]
    eye = [0.4, 2.2, -5.5]
    look_at = [0, 0.6, 0]
    fov = 45
    [[light]]
    position = [-4, 6, -5]
    [material.floor]
    checker = { colors = [[0.9, 0.9, 0.9], [0.2, 0.25, 0.3]], size = 0.5 }
    [material.red]
    color = [0.8, 0.2, 0.2]
    specular = 0.5
    [material.gold]
    color = [0.9, 0.7, 0.3]
    reflection = 0.3
    [[object]]
    type = "rectangle"
    corner = [-4, 0, -3]
    edge_u = [8, 0, 0]
    edge_v = [0, 0, 8]
    material = "floor"
    [[object]]
    type = "sphere"
    center = [-1.3, 0.7, 0]
    radius = 0.7
    material = "red"
    [[object]]
    type = "box"
    min = [1.6, 0, 1]
    max = [2.4, 0.8, 1.8]
    material = "gold"
    [[object]]
    type = "parametric"
    x = "(1 + 0.3*cos(v))*cos(u)"
    y = "0.3*sin(v)"
    z = "(1 + 0.3*cos(v))*sin(u)"
    u = [0, "2*pi"]
    v = [0, "2*pi"]
    transform = { scale = 0.6, translate = [0.4, 0.2, -0.8] }
    material = "gold"
    [[object]]
    type = "implicit"
    function = "x^2 + y^2 + z^2 - 0.25"
    box = { min = [-0.6, -0.6, -0.6], max = [0.6, 0.6, 0.6] }
    transform = { translate = [1.1, 0.5, -1.5] }
    material = "red"
)toml";

class FarFromOrigin : public testing::TestWithParam<double> {};

// The offsets are whole periods of the checker (2 x 0.5), so the moved scene is the same picture;
// the GPU's anchor (the eye) is not, so the checker's phase is exercised.
TEST_P(FarFromOrigin, TheGpuDrawsThePictureItDrawsAtTheOrigin) {
    const Scene scene = test::scene_from_text(kScene);
    const double offset = GetParam();
    const Rgb8Image at_origin = to_srgb8(test::render_on(test::Backend::Gpu, scene));
    const Rgb8Image far = to_srgb8(test::render_on(test::Backend::Gpu, test::moved_scene(scene, {offset, -offset, 3 * offset})));
    test::expect_same_picture("far_from_origin_gpu", at_origin, far);
    EXPECT_TRUE(test::gpu_renderer().notes().empty());
    // And the CPU reference, in double, agrees with both.
    const Rgb8Image reference = to_srgb8(test::render_on(test::Backend::Cpu, test::moved_scene(scene, {offset, -offset, 3 * offset})));
    test::expect_same_picture("far_from_origin_cpu", reference, far);
}

INSTANTIATE_TEST_SUITE_P(Offsets, FarFromOrigin, testing::Values(1e4, 1e6, 1e9));

// A ball and a block resting on a floor whose data lies far from the camera though the floor
// passes under it: a plane whose point is 10^6 away, a rectangle and a box with corners at
// 10^6, and a plane whose default point [0, 0, 0] is 10^6 from a scene moved there. Their error
// bounds grew with those distances and secondary rays started far off the floor: the contact
// shadows were gone (2.3% of the pixels). The shader now gets the floor's point nearest the
// camera, and a box's bound counts only the face hit.
TEST(FarAnchors, FloorsReachingFarKeepTheirContactShadows) {
    const std::string stage = R"(
        [render]
        width = 96
        height = 64
        samples = 2
        [camera]
        eye = [0.4, 1.6, -3.5]
        look_at = [0, 0.3, 0]
        fov = 45
        [[light]]
        position = [-4, 6, -2]
        [material.floor]
        checker = { colors = [[0.9, 0.9, 0.9], [0.2, 0.25, 0.3]], size = 0.5 }
        [material.red]
        color = [0.8, 0.2, 0.2]
        specular = 0.5
        [[object]]
        type = "sphere"
        center = [0, 0.5, 0]
        radius = 0.5
        material = "red"
        [[object]]
        type = "box"
        min = [0.7, 0, -0.4]
        max = [1.2, 0.3, 0.1]
        material = "red"
        [[object]]
        material = "floor"
    )";
    const std::pair<const char*, std::string> floors[] = {
        {"plane-point-far", "type = \"plane\"\npoint = [1e6, 0, 1e6]\nnormal = [0, 1, 0]\n"},
        {"rectangle-corners-far", "type = \"rectangle\"\ncorner = [-1e6, 0, -1e6]\nedge_u = [2e6, 0, 0]\nedge_v = [0, 0, 2e6]\n"},
        {"box-corners-far", "type = \"box\"\nmin = [-1e6, -1, -1e6]\nmax = [1e6, 0, 1e6]\n"},
        {"default-plane-moved-far", "type = \"plane\"\nnormal = [0, 1, 0]\n"},
    };
    for (const auto& [name, floor] : floors) {
        SCOPED_TRACE(name);
        Scene scene = test::scene_from_text(stage + floor);
        if (std::string(name) == "default-plane-moved-far") {
            const Plane plane = std::get<Plane>(scene.objects[2].shape);
            scene = test::moved_scene(scene, {1e6, 0, 0});
            scene.objects[2].shape = plane;  // the default point stays where it was
        }
        test::expect_same_picture(std::string("far-anchor-") + name, to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                                  to_srgb8(test::render_on(test::Backend::Cpu, scene)));
    }
}

// A sphere as the ground (a POV-Ray habit): radius R, centre R below two unit balls resting on
// it. Float placed its centre to 2^-24 R, far coarser than the picture's detail near the camera
// (R = 10^6: contact shadows gone, 10% of the pixels; 10^4: 26%); such scenes pack spheres by
// their points nearest the camera (SPHERES_BY_NEAR_POINTS, shaders/shapes/sphere.glsl).
TEST(FarAnchors, AGroundSphereFarLargerThanItsDistanceIsTheReferences) {
    for (double radius : {1e3, 1e4, 1e6}) {
        SCOPED_TRACE(radius);
        const Scene scene = test::scene_from_text(fmt::format(R"(
            [render]
            width = 96
            height = 64
            samples = 2
            [camera]
            eye = [2, 14, -6]
            look_at = [0, 0.5, 0]
            fov = 30
            [[light]]
            position = [-6, 10, -8]
            [material.floor]
            checker = {{ colors = [[0.9, 0.9, 0.9], [0.2, 0.25, 0.3]], size = 0.5 }}
            [material.red]
            color = [0.8, 0.2, 0.2]
            specular = 0.5
            [[object]]
            type = "sphere"
            center = [-1.2, 1, 0]
            radius = 1
            material = "red"
            [[object]]
            type = "sphere"
            center = [1.2, 1, 0.5]
            radius = 1
            material = "red"
            [[object]]
            type = "sphere"
            center = [0, {}, 0]
            radius = {}
            material = "floor"
        )", -radius, radius));
        EXPECT_TRUE(gpu::pack_scene(scene).features.spheres_by_near_points);
        test::expect_same_picture(fmt::format("ground-sphere-{}", radius), to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                                  to_srgb8(test::render_on(test::Backend::Cpu, scene)));
    }
    // Spheres of the picture's own scale keep their centres.
    EXPECT_FALSE(gpu::pack_scene(test::scene_from_text(kScene)).features.spheres_by_near_points);
}

TEST(FloatAnchor, IsTheOriginNearItAndTheEyeFarFromIt) {
    CameraSpec camera;
    camera.eye = {3.0, -1000.0, 20.0};
    EXPECT_EQ(gpu::float_anchor(camera), glm::dvec3(0.0));
    camera.eye = {1e6 + 0.3, -2e6 + 7.1, 5.5};
    EXPECT_EQ(gpu::float_anchor(camera), camera.eye);
}

TEST(FloatAnchor, TheCheckerPhaseKeepsEveryCellsParity) {
    const double size = 0.3;
    for (const glm::dvec3 anchor : {glm::dvec3(1e6 + 0.1, -3.7e5 + 0.013, 12345.678), glm::dvec3(-0.05, 0.0, 7.0)}) {
        const glm::dvec3 phase = gpu::checker_phase(anchor, size);
        for (int i = 0; i < 3; ++i) {
            EXPECT_GE(phase[i], 0.0);
            EXPECT_LT(phase[i], 2.0 * size);
        }
        for (double p : {-1.04, -0.2, 0.0, 0.55, 2.9}) {
            for (int i = 0; i < 3; ++i) {
                const double a = std::floor((p + anchor[i]) / size), b = std::floor((p + phase[i]) / size);
                EXPECT_EQ(std::fmod(std::abs(a - b), 2.0), 0.0) << "axis " << i << " at " << p;
            }
        }
    }
}

// A speck far from the camera, far below what float resolves there: the GPU says so.
TEST(FloatAnchor, AnObjectTooSmallForItsDistanceIsNamedInTheNotes) {
    Scene scene = test::scene_from_text(std::string(kScene) + R"(
        [[object]]
        name = "speck"
        type = "sphere"
        center = [0, 0.5, 3000]
        radius = 1e-6
        material = "red"
    )");
    scene.render.width = 8;
    scene.render.height = 8;
    test::render_on(test::Backend::Gpu, scene);
    const std::vector<std::string> notes = test::gpu_renderer().notes();
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("'speck'"), std::string::npos) << notes[0];
    EXPECT_NE(notes[0].find("--backend cpu"), std::string::npos) << notes[0];
}

}  // namespace
}  // namespace lancer

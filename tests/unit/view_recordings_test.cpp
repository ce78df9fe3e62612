// The sequences f and l record are animations of the animation model, the same ones a scene file
// would describe with the defaults of [animation.camera_orbit] and [[animation.light_orbit]].
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/animation.hpp"
#include "support/test_support.hpp"
#include "view/camera_text.hpp"
#include "view/recordings.hpp"

namespace lancer::view {
namespace {

const char* kScene = R"(
[camera]
eye = [1, 3.2, -9]
look_at = [0.5, 0.9, 0.25]
fov = 45
[[light]]
position = [-6, 10, -6]
[[light]]
position = [6, 10, -6]
[[object]]
type = "sphere"
center = [0, 1, 0]
radius = 1
)";

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(Recordings, OrbitIsTheCameraOrbitTableWithItsDefaults) {
    Scene scene = test::scene_from_text(kScene);
    Scene recorded = orbit_recording(scene, scene.camera, 12);
    // The same orbit, to the bit, as the file's defaults make it.
    Scene table = test::scene_from_text(std::string(kScene) + "[animation]\nframes = 12\ncyclic = true\n"
                                                                "[animation.camera_orbit]\n");
    const Orbit& a = *recorded.animation->camera_orbit;
    const Orbit& b = *table.animation->camera_orbit;
    EXPECT_EQ(a.center, b.center);
    EXPECT_TRUE(same_bits(a.radius, b.radius));
    EXPECT_TRUE(same_bits(a.height, b.height));
    EXPECT_TRUE(same_bits(a.start_angle_deg, b.start_angle_deg));
    EXPECT_EQ(a.turns, 1.0);
    EXPECT_EQ(recorded.animation->frames, 12);
    EXPECT_TRUE(recorded.animation->cyclic);
    EXPECT_EQ(recorded.animation->fps, kRecordFps);
    // Frame 0 is the current view; every frame looks at look_at from the same distance.
    double d = glm::length(scene.camera.eye - scene.camera.look_at);
    for (int k = 0; k < 12; ++k) {
        Scene f = scene_at(recorded, frame_time(*recorded.animation, k));
        EXPECT_EQ(f.camera.look_at, scene.camera.look_at);
        EXPECT_NEAR(glm::length(f.camera.eye - f.camera.look_at), d, 1e-12);
        if (k == 0) {
            EXPECT_NEAR(glm::length(f.camera.eye - scene.camera.eye), 0.0, 1e-12);
        }
    }
}

TEST(Recordings, OrbitStartsFromTheCurrentViewNotTheFiles) {
    Scene scene = test::scene_from_text(kScene);
    CameraSpec moved = scene.camera;
    moved.eye = {4, 2, 4};
    moved.up = {0.3, 0.9, 0.1};  // a rolled view: the orbit records without the roll
    Scene recorded = orbit_recording(scene, moved, 4);
    Scene f0 = scene_at(recorded, 0.0);
    EXPECT_NEAR(glm::length(f0.camera.eye - moved.eye), 0.0, 1e-12);
    EXPECT_EQ(f0.camera.up, dvec3(0, 1, 0));
}

TEST(Recordings, LightCirclesTheLookAtPointAndNothingElseMoves) {
    Scene scene = test::scene_from_text(kScene);
    CameraSpec view = scene.camera;
    view.eye = {2, 2, -5};
    Scene recorded = light_recording(scene, view, 8);
    ASSERT_EQ(recorded.animation->light_orbits.size(), 1u);
    const Orbit& o = recorded.animation->light_orbits[0].orbit;
    EXPECT_EQ(o.center, view.look_at);
    for (int k = 0; k < 8; ++k) {
        Scene f = scene_at(recorded, frame_time(*recorded.animation, k));
        EXPECT_EQ(f.camera.eye, view.eye);
        EXPECT_EQ(f.lights[1].position, scene.lights[1].position);
        dvec3 rel = f.lights[0].position - view.look_at;
        EXPECT_NEAR(std::hypot(rel.x, rel.z), o.radius, 1e-12);
        EXPECT_NEAR(f.lights[0].position.y, scene.lights[0].position.y, 1e-12);
        if (k == 0) {
            EXPECT_NEAR(glm::length(f.lights[0].position - scene.lights[0].position), 0.0, 1e-12);
        }
        if (k == 4) {  // half way round: opposite, at the same height
            dvec3 opposite = 2.0 * view.look_at - scene.lights[0].position;
            opposite.y = scene.lights[0].position.y;
            EXPECT_NEAR(glm::length(f.lights[0].position - opposite), 0.0, 1e-9);
        }
    }
}

TEST(Recordings, ImpossibleSequencesAreClearErrors) {
    Scene scene = test::scene_from_text(kScene);
    CameraSpec above = scene.camera;
    above.eye = above.look_at + dvec3(0, 5, 0);
    above.up = {0, 0, 1};
    EXPECT_THROW(orbit_recording(scene, above, 10), UserError);
    Scene dark = scene;
    dark.lights.clear();
    EXPECT_THROW(light_recording(dark, scene.camera, 10), UserError);
    Scene overhead = scene;
    overhead.lights[0].position = scene.camera.look_at + dvec3(0, 4, 0);
    EXPECT_THROW(light_recording(overhead, scene.camera, 10), UserError);
}

TEST(Recordings, DescriptionNamesTheOrbit) {
    Scene scene = test::scene_from_text(kScene);
    std::string text = describe_recording(*orbit_recording(scene, scene.camera, 120).animation);
    EXPECT_NE(text.find("camera_orbit center [0.5, 0.9, 0.25]"), std::string::npos) << text;
    EXPECT_NE(text.find("120 frames at 30 fps, cyclic"), std::string::npos) << text;
}

// The camera the viewer prints reads back, as a scene file's camera table, to the same bits.
TEST(CameraText, RoundTripsThroughTheSceneLoader) {
    CameraSpec c;
    c.eye = {0.1 + 0.2, -1.0 / 3.0, 1e-7};
    c.look_at = {1e10, 2.5, 0.0};
    c.up = {0.0, 0.9688627859122259, 0.2475982675109022};
    c.fov_deg = 47.123456789;
    std::string toml = "camera = { " + camera_toml(c) + " }\n";
    Scene s = test::scene_from_text(toml);
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(same_bits(s.camera.eye[i], c.eye[i])) << toml;
        EXPECT_TRUE(same_bits(s.camera.look_at[i], c.look_at[i])) << toml;
        EXPECT_TRUE(same_bits(s.camera.up[i], c.up[i])) << toml;
    }
    EXPECT_TRUE(same_bits(s.camera.fov_deg, c.fov_deg)) << toml;
}

}  // namespace
}  // namespace lancer::view

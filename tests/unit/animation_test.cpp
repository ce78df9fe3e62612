// The animation model: the clock, orbits, keyframe interpolation, and scene_at().
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/animation.hpp"
#include "scene/camera.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// Every kind of animation, with keys that do not sit on 0 so that wrapping is exercised.
const std::string kEverything = R"(
    [animation]
    frames = 24
    fps = 12
    cyclic = CYCLIC
    [animation.camera_orbit]
    center = [1, 0.5, 2]
    radius = 6
    height = 2
    start_angle = 30
    turns = -2
    [[animation.light_orbit]]
    light = 0
    center = [0, 0, 0]
    turns = 1
    [[animation.light]]
    light = "fill"
    interpolation = "smooth"
    keys = [
      { time = 0.2, position = [5, 5, 0], color = [1, 0.5, 0.2] },
      { time = 0.6, position = [-5, 7, 1], color = [0.1, 0.9, 0.3] },
      { time = 0.8, position = [0, 9, -3], color = [0.5, 0.5, 0.5] },
    ]
    [[animation.object]]
    object = "ball"
    interpolation = "linear"
    keys = [
      { time = 0.1, translate = [0, 0, 0] },
      { time = 0.5, translate = [0, 2, 1] },
    ]
    [camera]
    eye = [0, 2, -8]
    look_at = [0, 0, 0]
    [[light]]
    position = [4, 6, -4]
    [[light]]
    name = "fill"
    position = [-4, 6, -4]
    [[object]]
    name = "ball"
    type = "sphere"
    center = [0, 1, 0]
    radius = 1
    [[object]]
    type = "box"
    min = [-1, 0, -1]
    max = [1, 1, 1]
)";

Scene everything(bool cyclic) {
    std::string text = kEverything;
    text.replace(text.find("CYCLIC"), 6, cyclic ? "true" : "false");
    return test::scene_from_text(text);
}

// Bit-for-bit equality of two shapes (the shape structs define no ==).
bool same_shape(const Shape& a, const Shape& b) {
    if (a.index() != b.index()) return false;
    return std::visit(
        [&](const auto& x) {
            using T = std::decay_t<decltype(x)>;
            return std::memcmp(&x, &std::get<T>(b), sizeof(T)) == 0;
        },
        a);
}

// Field-by-field equality of everything an animation can change.
void expect_same_moment(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.camera.eye, b.camera.eye);
    EXPECT_EQ(a.camera.look_at, b.camera.look_at);
    EXPECT_EQ(a.camera.up, b.camera.up);
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        EXPECT_EQ(a.lights[i].position, b.lights[i].position) << "light " << i;
        EXPECT_EQ(a.lights[i].color, b.lights[i].color) << "light " << i;
    }
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) EXPECT_TRUE(same_shape(a.objects[i].shape, b.objects[i].shape)) << "object " << i;
}

bool same_moment(const Scene& a, const Scene& b) {
    return a.camera.eye == b.camera.eye && a.lights[0].position == b.lights[0].position &&
           a.lights[1].position == b.lights[1].position && same_shape(a.objects[0].shape, b.objects[0].shape);
}

TEST(Animation, ClockRunsFrom0To1LikePovRayClock) {
    Animation a;
    a.frames = 5;
    EXPECT_EQ(frame_time(a, 0), 0.0);
    EXPECT_EQ(frame_time(a, 2), 0.5);
    EXPECT_EQ(frame_time(a, 4), 1.0);  // the last frame is at clock 1
    a.cyclic = true;                   // +KC: the last frame is one step short of 1
    EXPECT_EQ(frame_time(a, 4), 0.8);
    EXPECT_EQ(frame_time(a, 5), 1.0);
    a.frames = 1;
    a.cyclic = false;
    EXPECT_EQ(frame_time(a, 0), 0.0);
}

// The issue's cyclic test, through the time function: the frame after the last is frame 0,
// exactly, for every kind of animation at once.
TEST(Animation, CyclicFrameAfterTheLastIsFrameZero) {
    Scene scene = everything(true);
    const Animation& a = *scene.animation;
    Scene first = scene_at(scene, frame_time(a, 0));
    Scene after_last = scene_at(scene, frame_time(a, a.frames));
    expect_same_moment(after_last, first);
    // ...while the last frame really is a different picture (the test would pass vacuously otherwise).
    EXPECT_FALSE(same_moment(scene_at(scene, frame_time(a, a.frames - 1)), first));
    // and every frame differs from its neighbours
    for (int k = 0; k < a.frames; ++k)
        EXPECT_FALSE(same_moment(scene_at(scene, frame_time(a, k)), scene_at(scene, frame_time(a, k + 1)))) << k;
}

TEST(Animation, NonCyclicAnimationEndsAtTheLastKeyNotTheFirst) {
    Scene scene = everything(false);
    const Animation& a = *scene.animation;
    Scene last = scene_at(scene, frame_time(a, a.frames - 1));
    EXPECT_EQ(last.lights[1].position, dvec3(0, 9, -3));                           // the last key, held
    EXPECT_EQ(std::get<Sphere>(last.objects[0].shape).center, dvec3(0, 3, 1));    // (0,1,0) + last key
    Scene first = scene_at(scene, 0.0);
    EXPECT_EQ(first.lights[1].position, dvec3(5, 5, 0));                          // the first key, held
}

TEST(Animation, CameraOrbitIsTheOriginalFormulaAndLooksAtTheCentre) {
    Scene scene = everything(false);
    // a = 30 - 720 t degrees; at t = 0.125 that is -60.
    Scene s = scene_at(scene, 0.125);
    double a = -60.0 * M_PI / 180.0;
    dvec3 expected = dvec3(1, 0.5, 2) + dvec3(std::cos(a) * 6, 2, std::sin(a) * 6);
    EXPECT_LT(glm::length(s.camera.eye - expected), 1e-12);
    EXPECT_EQ(s.camera.look_at, dvec3(1, 0.5, 2));
    EXPECT_EQ(s.camera.up, dvec3(0, 1, 0));  // the world's up; the basis re-derives the true up per frame
}

// The original project kept the first frame's up vector as the camera moved, so the basis
// stopped being orthogonal and pictures sheared. Every frame's basis here is orthonormal, looks
// at the centre, and keeps the horizon level (right has no vertical part: no roll).
TEST(Animation, OrbitCameraBasisIsOrthonormalAndLevelAtEveryFrame) {
    for (double height : {-7.0, 0.0, 0.5, 3.0, 40.0}) {
        Scene scene = test::scene_from_text(
            "[animation]\nframes = 36\ncyclic = true\n[animation.camera_orbit]\ncenter = [1, 2, 3]\nradius = 5\n"
            "height = " + std::to_string(height) + "\nstart_angle = 10\n[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n");
        for (int k = 0; k < 36; ++k) {
            Scene s = scene_at(scene, frame_time(*scene.animation, k));
            CameraBasis b = make_camera_basis(s.camera, 100, 100);
            dvec3 f = b.forward, r = glm::normalize(b.right), u = glm::normalize(b.up);
            SCOPED_TRACE("height " + std::to_string(height) + ", frame " + std::to_string(k));
            EXPECT_NEAR(glm::dot(f, r), 0.0, 1e-12);
            EXPECT_NEAR(glm::dot(f, u), 0.0, 1e-12);
            EXPECT_NEAR(glm::dot(r, u), 0.0, 1e-12);
            EXPECT_NEAR(r.y, 0.0, 1e-12);  // level horizon
            EXPECT_GT(u.y, 0.0);           // not upside down
            EXPECT_LT(glm::length(glm::cross(f, glm::normalize(dvec3(1, 2, 3) - s.camera.eye))), 1e-12);
        }
    }
}

TEST(Animation, OrbitDefaultsStartWhereTheFilePutsTheCameraAndLight) {
    Scene scene = test::scene_from_text(R"(
        [animation]
        frames = 10
        [animation.camera_orbit]
        [[animation.light_orbit]]
        light = 0
        center = [1, 0, 1]
        [camera]
        eye = [3, 4, -7]
        look_at = [0.5, 1, 0.25]
        [[light]]
        position = [-2, 9, 5]
    )");
    Scene s = scene_at(scene, 0.0);
    EXPECT_LT(glm::length(s.camera.eye - dvec3(3, 4, -7)), 1e-12);
    EXPECT_EQ(s.camera.look_at, dvec3(0.5, 1, 0.25));
    EXPECT_LT(glm::length(s.lights[0].position - dvec3(-2, 9, 5)), 1e-12);
    // Half way round (one turn by default): mirrored through the axis.
    Scene half = scene_at(scene, 0.5);
    EXPECT_LT(glm::length(half.camera.eye - dvec3(-2, 4, 7.5)), 1e-12);
    EXPECT_LT(glm::length(half.lights[0].position - dvec3(4, 9, -3)), 1e-12);
}

TEST(Animation, ObjectKeysTranslateEveryShapeKind) {
    dvec3 d(1, -2, 3);
    Shape sphere = Sphere{{0, 1, 0}, 2};
    Shape plane = Plane{{0, 0, 0}, {0, 1, 0}};
    Shape rect = Rectangle{{1, 1, 1}, {1, 0, 0}, {0, 0, 1}};
    Shape box = Box{{0, 0, 0}, {1, 1, 1}};
    translate(sphere, d);
    translate(plane, d);
    translate(rect, d);
    translate(box, d);
    EXPECT_EQ(std::get<Sphere>(sphere).center, dvec3(1, -1, 3));
    EXPECT_EQ(std::get<Sphere>(sphere).radius, 2.0);
    EXPECT_EQ(std::get<Plane>(plane).point, d);
    EXPECT_EQ(std::get<Plane>(plane).normal, dvec3(0, 1, 0));
    EXPECT_EQ(std::get<Rectangle>(rect).corner, dvec3(2, -1, 4));
    EXPECT_EQ(std::get<Rectangle>(rect).edge_u, dvec3(1, 0, 0));
    EXPECT_EQ(std::get<Box>(box).min, d);
    EXPECT_EQ(std::get<Box>(box).max, dvec3(2, -1, 4));
}

TEST(Animation, SceneWithoutAnimationIsReturnedAsItIs) {
    Scene scene = test::scene_from_text("[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n[[object]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\n");
    EXPECT_FALSE(scene.animation);
    Scene s = scene_at(scene, 0.7);
    EXPECT_EQ(s.camera.eye, scene.camera.eye);
    EXPECT_TRUE(same_shape(s.objects[0].shape, scene.objects[0].shape));
}

TEST(Animation, StaticSceneOfAMomentCarriesNoAnimation) {
    EXPECT_FALSE(scene_at(everything(true), 0.3).animation);
}

Track track(std::vector<double> times, std::vector<dvec3> values, Interpolation i) { return {std::move(times), std::move(values), i}; }

TEST(Track, LinearPassesThroughKeysAndHoldsOutside) {
    Track t = track({0.2, 0.6}, {dvec3(0), dvec3(4, 8, -4)}, Interpolation::Linear);
    EXPECT_EQ(sample(t, 0.0, false), dvec3(0));
    EXPECT_EQ(sample(t, 0.2, false), dvec3(0));
    EXPECT_LT(glm::length(sample(t, 0.4, false) - dvec3(2, 4, -2)), 1e-12);
    EXPECT_EQ(sample(t, 0.6, false), dvec3(4, 8, -4));
    EXPECT_EQ(sample(t, 1.0, false), dvec3(4, 8, -4));
}

TEST(Track, CyclicTrackWrapsFromTheLastKeyToTheFirst) {
    Track t = track({0.25, 0.75}, {dvec3(0), dvec3(4)}, Interpolation::Linear);
    EXPECT_EQ(sample(t, 0.5, true), dvec3(2));
    EXPECT_EQ(sample(t, 0.0, true), dvec3(2));   // half way from 4 (at 0.75) back to 0 (at 1.25)
    EXPECT_EQ(sample(t, 1.0, true), dvec3(2));
    EXPECT_EQ(sample(t, 0.875, true), dvec3(3));
    EXPECT_EQ(sample(t, 0.125, true), dvec3(1));
}

TEST(Track, SmoothPassesThroughKeysWithContinuousVelocityAndStartsAndStopsAtRest) {
    Track t = track({0.0, 0.3, 0.5, 1.0}, {dvec3(0), dvec3(3, 1, 0), dvec3(1, 4, 2), dvec3(-2, 0, 5)}, Interpolation::Smooth);
    for (std::size_t i = 0; i < t.times.size(); ++i) EXPECT_EQ(sample(t, t.times[i], false), t.values[i]) << i;
    // C1 at the inner keys: left and right one-sided velocities agree.
    for (double k : {0.3, 0.5}) {
        double h = 1e-7;
        dvec3 left = (sample(t, k, false) - sample(t, k - h, false)) / h;
        dvec3 right = (sample(t, k + h, false) - sample(t, k, false)) / h;
        EXPECT_LT(glm::length(left - right), 1e-3 * (1 + glm::length(left))) << k;
        EXPECT_GT(glm::length(left), 1.0) << "inner keys are passed through, not stopped at";
    }
    // At rest at both ends: the one-sided velocity over a tiny step is about as tiny.
    double h = 1e-6;
    EXPECT_LT(glm::length(sample(t, h, false) - sample(t, 0.0, false)) / h, 1e-3);
    EXPECT_LT(glm::length(sample(t, 1.0, false) - sample(t, 1.0 - h, false)) / h, 1e-3);
    // It is not linear: a quarter of the way into the first segment it has not covered a quarter.
    EXPECT_LT(sample(t, 0.075, false).x, 0.75);
}

TEST(Track, SmoothCyclicTrackHasNoKinkAtTheWrap) {
    Track t = track({0.1, 0.4, 0.7}, {dvec3(0), dvec3(2, 0, 0), dvec3(1, 3, 0)}, Interpolation::Smooth);
    EXPECT_EQ(sample(t, 0.0, true), sample(t, 1.0, true));
    for (double k : {0.1, 0.4, 0.7, 0.0}) {
        double h = 1e-7;
        dvec3 left = (sample(t, k, true) - sample(t, k - h, true)) / h;
        dvec3 right = (sample(t, k + h, true) - sample(t, k, true)) / h;
        EXPECT_LT(glm::length(left - right), 1e-3 * (1 + glm::length(left))) << k;
    }
}

TEST(Track, SmoothColourNeverGoesBelowBlack) {
    // A spline through 1, 0, 1 dips below 0 between the keys; light colours are clamped there.
    Scene scene = test::scene_from_text(R"(
        [animation]
        frames = 50
        [[animation.light]]
        light = 0
        interpolation = "smooth"
        keys = [
          { time = 0.0, color = [1, 1, 1] },
          { time = 0.1, color = [0, 0, 0] },
          { time = 0.9, color = [0, 0, 0] },
          { time = 1.0, color = [1, 1, 1] },
        ]
        [camera]
        eye = [0, 0, -5]
        look_at = [0, 0, 0]
        [[light]]
        position = [0, 5, 0]
    )");
    const Track& color = *scene.animation->light_keys[0].color;
    EXPECT_LT(sample(color, 0.15, false).r, 0.0) << "the raw spline must overshoot, or this test shows nothing";
    for (int k = 0; k < 50; ++k) {
        dvec3 c = scene_at(scene, frame_time(*scene.animation, k)).lights[0].color;
        EXPECT_GE(c.r, 0.0) << k;
    }
}

TEST(AnimationLoader, ReadsTheWholeVocabulary) {
    Scene scene = everything(true);
    ASSERT_TRUE(scene.animation);
    const Animation& a = *scene.animation;
    EXPECT_EQ(a.frames, 24);
    EXPECT_EQ(a.fps, 12.0);
    EXPECT_TRUE(a.cyclic);
    ASSERT_TRUE(a.camera_orbit);
    EXPECT_EQ(a.camera_orbit->turns, -2.0);
    EXPECT_EQ(a.camera_orbit->start_angle_deg, 30.0);
    ASSERT_EQ(a.light_orbits.size(), 1u);
    EXPECT_EQ(a.light_orbits[0].light, 0u);
    ASSERT_EQ(a.light_keys.size(), 1u);
    EXPECT_EQ(a.light_keys[0].light, 1u);  // by name
    ASSERT_TRUE(a.light_keys[0].position && a.light_keys[0].color);
    EXPECT_EQ(a.light_keys[0].position->interpolation, Interpolation::Smooth);
    EXPECT_EQ(a.light_keys[0].position->times.size(), 3u);
    ASSERT_EQ(a.object_keys.size(), 1u);
    EXPECT_EQ(a.object_keys[0].object, 0u);
    EXPECT_EQ(scene.objects[0].name, "ball");
    EXPECT_EQ(scene.lights[1].name, "fill");
}

TEST(AnimationLoader, DefaultsAreThirtyFpsAndNotCyclic) {
    Scene scene = test::scene_from_text("[animation]\nframes = 3\n[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n");
    EXPECT_EQ(scene.animation->fps, 30.0);
    EXPECT_FALSE(scene.animation->cyclic);
    EXPECT_FALSE(scene.animation->camera_orbit);
}

}  // namespace
}  // namespace lancer

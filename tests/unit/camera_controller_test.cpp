// The viewer's camera moves: each documented step, exactly; and through long random sequences of
// moves the up vector stays unit length, perpendicular to the view, and unrolled unless w or x
// rolled it.
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/camera.hpp"
#include "view/camera_controller.hpp"

namespace lancer::view {
namespace {

const dvec3 kVertical{0.0, 1.0, 0.0};

// scenes/seed.toml's camera: looking down at the scene, up = [0, 1, 0] (not perpendicular).
CameraSpec seed_camera() {
    CameraSpec c;
    c.eye = {0.0, 3.2, -9.0};
    c.look_at = {0.0, 0.9, 0.0};
    c.up = {0.0, 1.0, 0.0};
    c.fov_deg = 45.0;
    return c;
}

double distance(const CameraSpec& c) { return glm::length(c.look_at - c.eye); }
dvec3 forward(const CameraSpec& c) { return glm::normalize(c.look_at - c.eye); }

void expect_near(const dvec3& a, const dvec3& b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// Unit up, perpendicular to the view: nothing for rounding to build on.
void expect_orthonormal(const CameraSpec& c) {
    EXPECT_NEAR(glm::length(c.up), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(c.up, forward(c)), 0.0, 1e-12);
}

double degrees_between(const dvec3& a, const dvec3& b) {
    double c = glm::dot(glm::normalize(a), glm::normalize(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
}

TEST(CameraController, NRightStepsMoveByTheDocumentedTranslation) {
    const CameraSpec start = seed_camera();
    const double d = distance(start);
    // The camera's right vector as make_camera_basis builds it.
    CameraBasis basis = make_camera_basis(start, 640, 480);
    const dvec3 right = glm::normalize(basis.right);
    for (int n : {1, 4, 25}) {
        CameraController c(start);
        for (int i = 0; i < n; ++i) c.move(CameraMove::Right);
        dvec3 step = right * (n * 0.05 * d);  // the documented step: 5% of the distance
        expect_near(c.camera().eye, start.eye + step, 1e-12 * n);
        expect_near(c.camera().look_at, start.look_at + step, 1e-12 * n);
        EXPECT_NEAR(distance(c.camera()), d, 1e-12);
        expect_near(forward(c.camera()), forward(start), 1e-15);
        expect_orthonormal(c.camera());
    }
}

TEST(CameraController, ArrowsMoveAlongTheCamerasAxesAndUndoEachOther) {
    const CameraSpec start = seed_camera();
    CameraBasis basis = make_camera_basis(start, 640, 480);
    const dvec3 up = glm::normalize(basis.up);
    CameraSpec c = apply_move(start, CameraMove::Up, kVertical);
    expect_near(c.eye, start.eye + up * (0.05 * distance(start)), 1e-12);
    c = apply_move(c, CameraMove::Down, kVertical);
    expect_near(c.eye, start.eye, 1e-12);
    c = apply_move(apply_move(start, CameraMove::Right, kVertical), CameraMove::Left, kVertical);
    expect_near(c.eye, start.eye, 1e-12);
    expect_near(c.look_at, start.look_at, 1e-12);
}

TEST(CameraController, OrbitKeepsTheDistanceAndLookAtAndGoesRoundInSeventyTwoSteps) {
    const CameraSpec start = seed_camera();
    const double d = distance(start);
    CameraSpec c = start;
    for (int i = 0; i < 72; ++i) {
        c = apply_move(c, CameraMove::OrbitRight, kVertical);
        EXPECT_NEAR(distance(c), d, 1e-12);
        EXPECT_EQ(c.look_at, start.look_at);
        EXPECT_NEAR(c.eye.y, start.eye.y, 1e-12);  // a turntable: the height stays
        expect_orthonormal(c);
    }
    expect_near(c.eye, start.eye, 1e-10);  // 72 x 5 degrees
    // d moves the eye to the camera's right, q to its left, and they undo each other.
    dvec3 right = camera_right(start);
    EXPECT_GT(glm::dot(apply_move(start, CameraMove::OrbitRight, kVertical).eye - start.eye, right), 0.0);
    EXPECT_LT(glm::dot(apply_move(start, CameraMove::OrbitLeft, kVertical).eye - start.eye, right), 0.0);
    CameraSpec back = apply_move(apply_move(start, CameraMove::OrbitRight, kVertical), CameraMove::OrbitLeft, kVertical);
    expect_near(back.eye, start.eye, 1e-12);
}

TEST(CameraController, OrbitTurnsByTheDocumentedAngle) {
    const CameraSpec start = seed_camera();
    CameraSpec c = apply_move(start, CameraMove::OrbitRight, kVertical);
    // Seen from above, the eye turned the documented 5 degrees about the vertical through look_at.
    dvec3 a = start.eye - start.look_at, b = c.eye - c.look_at;
    EXPECT_NEAR(degrees_between({a.x, 0, a.z}, {b.x, 0, b.z}), 5.0, 1e-9);
}

TEST(CameraController, RollChangesOnlyUpByTheDocumentedAngle) {
    const CameraSpec start = orthonormalize(seed_camera());
    CameraSpec c = apply_move(start, CameraMove::RollLeft, kVertical);
    EXPECT_EQ(c.eye, start.eye);
    EXPECT_EQ(c.look_at, start.look_at);
    EXPECT_NEAR(degrees_between(c.up, start.up), 5.0, 1e-9);
    expect_orthonormal(c);
    // w turns the camera anticlockwise as it looks: its up leans to its left.
    EXPECT_LT(glm::dot(c.up, camera_right(start)), 0.0);
    CameraSpec back = apply_move(c, CameraMove::RollRight, kVertical);
    expect_near(back.up, start.up, 1e-12);
    for (int i = 0; i < 72; ++i) c = apply_move(c, CameraMove::RollRight, kVertical);  // a whole turn back
    expect_near(c.up, apply_move(start, CameraMove::RollLeft, kVertical).up, 1e-10);
}

TEST(CameraController, DollyScalesTheDistanceAlongTheView) {
    const CameraSpec start = seed_camera();
    CameraSpec in = apply_move(start, CameraMove::DollyIn, kVertical);
    EXPECT_NEAR(distance(in), distance(start) * 0.9, 1e-12);
    EXPECT_EQ(in.look_at, start.look_at);
    expect_near(forward(in), forward(start), 1e-15);
    CameraSpec out = apply_move(in, CameraMove::DollyOut, kVertical);
    expect_near(out.eye, start.eye, 1e-12);
    // However far in, never onto look_at (the picture would be undefined).
    CameraSpec c = start;
    for (int i = 0; i < 2000; ++i) c = apply_move(c, CameraMove::DollyIn, kVertical);
    EXPECT_GT(distance(c), 0.0);
    EXPECT_NO_THROW(make_camera_basis(c, 64, 64));
}

TEST(CameraController, DragTurnsTheSceneWithTheMouse) {
    CameraController c(seed_camera());
    const CameraSpec start = c.camera();
    c.drag(10, 0);  // right: the scene turns right, so the eye goes to the camera's left
    EXPECT_LT(glm::dot(c.camera().eye - start.eye, camera_right(start)), 0.0);
    EXPECT_NEAR(distance(c.camera()), distance(start), 1e-12);
    c.reset();
    c.drag(0, 10);  // down: the scene's top comes forward, so the eye rises
    EXPECT_GT(c.camera().eye.y, start.eye.y);
    EXPECT_NEAR(distance(c.camera()), distance(start), 1e-12);
    EXPECT_NEAR(roll_degrees(c.camera(), kVertical), 0.0, 1e-12);
}

TEST(CameraController, WheelDolliesOneStepPerNotch) {
    CameraController c(seed_camera());
    double d = distance(c.camera());
    c.wheel(3);
    EXPECT_NEAR(distance(c.camera()), d * std::pow(0.9, 3), 1e-12);
    c.wheel(-3);
    EXPECT_NEAR(distance(c.camera()), d, 1e-12);
}

TEST(CameraController, ResetRestoresTheFilesCameraExactly) {
    const CameraSpec file = seed_camera();
    CameraController c(file);
    EXPECT_EQ(c.camera().up, file.up);  // untouched until a move, so the first picture is `lancer render`'s
    c.move(CameraMove::OrbitLeft);
    c.move(CameraMove::RollRight);
    c.drag(33, -12);
    c.reset();
    EXPECT_EQ(c.camera().eye, file.eye);
    EXPECT_EQ(c.camera().look_at, file.look_at);
    EXPECT_EQ(c.camera().up, file.up);
    EXPECT_EQ(c.camera().fov_deg, file.fov_deg);
}

TEST(CameraController, AReloadedSceneKeepsTheViewUnlessItsCameraChanged) {
    CameraController c(seed_camera());
    c.move(CameraMove::Right);
    CameraSpec moved = c.camera();
    c.set_home(seed_camera());
    EXPECT_EQ(c.camera().eye, moved.eye);
    CameraSpec other = seed_camera();
    other.eye.x = 2.0;
    c.set_home(other);
    EXPECT_EQ(c.camera().eye, other.eye);
    c.move(CameraMove::Left);
    c.reset();
    EXPECT_EQ(c.camera().eye, other.eye);
}

// Thousands of random moves without w or x: up stays orthonormal and the roll stays what it was
// (zero for the seed camera, and 15 degrees after three rolls), even through orbits over the
// top. The same sequence with rolls in it ends where its rolls alone would put it.
TEST(CameraController, NoShearAndNoCreepingRollThroughLongSequences) {
    std::mt19937 rng(8);
    const CameraMove unrolling[] = {CameraMove::Right, CameraMove::Left, CameraMove::Up, CameraMove::Down,
                                    CameraMove::OrbitLeft, CameraMove::OrbitRight, CameraMove::DollyIn,
                                    CameraMove::DollyOut};
    for (int rolls : {0, 3}) {
        CameraController c(seed_camera());
        for (int i = 0; i < rolls; ++i) c.move(CameraMove::RollLeft);
        const double roll = roll_degrees(c.camera(), kVertical);
        const double d = distance(c.camera());
        std::uniform_int_distribution<int> pick(0, 9);
        std::uniform_real_distribution<double> drag(-40.0, 40.0);
        int dolly = 0;
        for (int i = 0; i < 20000; ++i) {
            int k = pick(rng);
            if (k < 8) {
                CameraMove m = unrolling[k];
                // Keep the distance bounded so the tolerance below means the same throughout.
                if (m == CameraMove::DollyIn && dolly > 5) m = CameraMove::DollyOut;
                if (m == CameraMove::DollyOut && dolly < -5) m = CameraMove::DollyIn;
                dolly += m == CameraMove::DollyIn ? 1 : m == CameraMove::DollyOut ? -1 : 0;
                c.move(m);
            } else {
                c.drag(drag(rng), drag(rng));
            }
            expect_orthonormal(c.camera());
            if (HasFailure()) return;
        }
        EXPECT_NEAR(roll_degrees(c.camera(), kVertical), roll, 1e-9) << rolls << " roll steps";
        EXPECT_NEAR(distance(c.camera()), d * std::pow(kDollyFactor, dolly), 1e-9 * d);
    }
}

TEST(CameraController, DegenerateCamerasAreRefusedLikeRenders) {
    CameraSpec c = seed_camera();
    c.up = c.look_at - c.eye;
    EXPECT_THROW(CameraController{c}, UserError);
}

}  // namespace
}  // namespace lancer::view

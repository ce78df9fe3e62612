#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/camera.hpp"

namespace lancer {
namespace {

TEST(Camera, DefaultViewIsLeftHandedXRightYUp) {
    CameraBasis c = make_camera_basis({{0, 0, -5}, {0, 0, 0}, {0, 1, 0}, 90.0}, 100, 100);
    EXPECT_NEAR(glm::length(c.forward - dvec3(0, 0, 1)), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(glm::normalize(c.right) - dvec3(1, 0, 0)), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(glm::normalize(c.up) - dvec3(0, 1, 0)), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(c.up), 1.0, 1e-12);  // tan(45 deg)
}

TEST(Camera, ImageCornersSpanTheFieldOfView) {
    CameraBasis c = make_camera_basis({{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 60.0}, 200, 100);
    dvec3 top_centre = glm::normalize(camera_ray_direction(c, 100, 0, 200, 100));
    EXPECT_NEAR(std::acos(glm::dot(top_centre, c.forward)) * 180.0 / M_PI, 30.0, 1e-9);
    dvec3 right_middle = camera_ray_direction(c, 200, 50, 200, 100);
    EXPECT_NEAR(right_middle.x, 2.0 * std::tan(M_PI / 6.0), 1e-12);  // aspect 2
}

// For arbitrary eye, target and up the basis is orthonormal, forward points at the target and
// "up" is the given up with its forward component removed (so the picture never shears).
TEST(Camera, BasisIsOrthonormalForArbitraryViews) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    for (int i = 0; i < 1000; ++i) {
        CameraSpec spec{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, 50.0};
        dvec3 f = glm::normalize(spec.look_at - spec.eye);
        if (glm::length(glm::cross(f, glm::normalize(spec.up))) < 1e-3) continue;
        CameraBasis c = make_camera_basis(spec, 64, 64);
        dvec3 r = glm::normalize(c.right), up = glm::normalize(c.up);
        EXPECT_NEAR(glm::dot(c.forward, f), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(r, up), 0.0, 1e-12);
        EXPECT_NEAR(glm::dot(r, c.forward), 0.0, 1e-12);
        EXPECT_NEAR(glm::dot(up, c.forward), 0.0, 1e-12);
        EXPECT_GT(glm::dot(up, spec.up), 0.0);  // not upside down
        EXPECT_NEAR(glm::dot(glm::cross(up, c.forward), r), 1.0, 1e-12);  // handedness fixed
        EXPECT_NEAR(glm::length(glm::normalize(camera_ray_direction(c, 32, 32, 64, 64)) - f), 0.0, 1e-12);
    }
}

TEST(Camera, DegenerateViewsAreErrors) {
    EXPECT_THROW(make_camera_basis({{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 60}, 10, 10), UserError);
    EXPECT_THROW(make_camera_basis({{0, 5, 0}, {0, 0, 0}, {0, 1, 0}, 60}, 10, 10), UserError);  // up parallel
    EXPECT_THROW(make_camera_basis({{0, 0, -5}, {0, 0, 0}, {0, 0, 0}, 60}, 10, 10), UserError);
    EXPECT_NO_THROW(make_camera_basis({{0, 5, 0}, {0, 0, 0}, {0, 0, 1}, 60}, 10, 10));  // looking down, z up
}

}  // namespace
}  // namespace lancer

#include "view/camera_controller.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "scene/camera.hpp"

namespace lancer::view {
namespace {

double radians(double degrees) { return degrees * (M_PI / 180.0); }

// Rodrigues' rotation of v by `angle` radians about the unit axis k (right-hand rule in the
// numbers; the scene's left-handedness only matters for which way is "right", handled below).
dvec3 rotate(const dvec3& v, const dvec3& k, double angle) {
    double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * (glm::dot(k, v) * (1.0 - c));
}

dvec3 view_direction(const CameraSpec& camera) { return glm::normalize(camera.look_at - camera.eye); }

double distance(const CameraSpec& camera) { return glm::length(camera.look_at - camera.eye); }

// The eye moved to `eye_offset` from look_at, with `up` turned alongside.
CameraSpec with_eye(const CameraSpec& camera, const dvec3& eye_offset, const dvec3& up) {
    CameraSpec c = camera;
    c.eye = camera.look_at + eye_offset;
    c.up = up;
    return orthonormalize(c);
}

CameraSpec translate(const CameraSpec& camera, const dvec3& unit_direction) {
    dvec3 step = unit_direction * (kMoveFraction * distance(camera));
    CameraSpec c = camera;
    c.eye += step;
    c.look_at += step;
    return orthonormalize(c);
}

CameraSpec roll(const CameraSpec& camera, double anticlockwise_deg) {
    // The camera turning anticlockwise (as it looks) tilts its up vector towards its left.
    double a = radians(anticlockwise_deg);
    CameraSpec c = camera;
    c.up = std::cos(a) * camera_up(camera) - std::sin(a) * camera_right(camera);
    return orthonormalize(c);
}

CameraSpec dolly(const CameraSpec& camera, double factor) {
    // Never onto look_at: the picture would be undefined. Far below any useful distance.
    double floor = 1e-9 * std::max({1.0, std::abs(camera.look_at.x), std::abs(camera.look_at.y), std::abs(camera.look_at.z)});
    double d = std::max(distance(camera) * factor, floor);
    CameraSpec c = camera;
    c.eye = camera.look_at - view_direction(camera) * d;
    return orthonormalize(c);
}

}  // namespace

CameraSpec orthonormalize(const CameraSpec& camera) {
    make_camera_basis(camera, 1, 1);  // the same checks and messages as every render
    CameraSpec c = camera;
    dvec3 f = view_direction(camera);
    c.up = glm::normalize(camera.up - glm::dot(camera.up, f) * f);
    return c;
}

dvec3 camera_right(const CameraSpec& camera) {
    return glm::normalize(glm::cross(camera.up, view_direction(camera)));
}

dvec3 camera_up(const CameraSpec& camera) {
    dvec3 f = view_direction(camera);
    return glm::cross(f, camera_right(camera));
}

double roll_degrees(const CameraSpec& camera, const dvec3& vertical) {
    double s = std::clamp(glm::dot(camera_right(camera), glm::normalize(vertical)), -1.0, 1.0);
    return std::asin(s) * (180.0 / M_PI);
}

CameraSpec orbit(const CameraSpec& camera, double right_deg, double up_deg, const dvec3& vertical) {
    CameraSpec c = camera;
    if (right_deg != 0.0) {
        // A positive turn about the vertical moves the eye to the camera's left (cross(up, forward)
        // is right in this left-handed system), hence the minus.
        dvec3 axis = glm::normalize(vertical);
        double a = -radians(right_deg);
        c = with_eye(c, rotate(c.eye - c.look_at, axis, a), rotate(camera_up(c), axis, a));
    }
    if (up_deg != 0.0) {
        // In the plane of the view direction and up: the eye rises, the view tilts down.
        double a = radians(up_deg);
        dvec3 f = view_direction(c), u = camera_up(c);
        dvec3 f2 = std::cos(a) * f - std::sin(a) * u;
        dvec3 u2 = std::cos(a) * u + std::sin(a) * f;
        c = with_eye(c, -f2 * distance(c), u2);
    }
    return c;
}

CameraSpec apply_move(const CameraSpec& camera, CameraMove move, const dvec3& vertical) {
    switch (move) {
        case CameraMove::Right: return translate(camera, camera_right(camera));
        case CameraMove::Left: return translate(camera, -camera_right(camera));
        case CameraMove::Up: return translate(camera, camera_up(camera));
        case CameraMove::Down: return translate(camera, -camera_up(camera));
        case CameraMove::OrbitLeft: return orbit(camera, -kOrbitDegrees, 0.0, vertical);
        case CameraMove::OrbitRight: return orbit(camera, kOrbitDegrees, 0.0, vertical);
        case CameraMove::RollLeft: return roll(camera, kRollDegrees);
        case CameraMove::RollRight: return roll(camera, -kRollDegrees);
        case CameraMove::DollyIn: return dolly(camera, kDollyFactor);
        case CameraMove::DollyOut: return dolly(camera, 1.0 / kDollyFactor);
    }
    return camera;
}

namespace {

// The file's camera is kept as it is (only checked), so the first picture and a reset are the
// very picture `lancer render` makes; moves orthonormalize what they return.
const CameraSpec& checked(const CameraSpec& camera) {
    orthonormalize(camera);
    return camera;
}

}  // namespace

CameraController::CameraController(const CameraSpec& home)
    : home_(checked(home)), camera_(home), vertical_(glm::normalize(home.up)) {}

void CameraController::drag(double dx, double dy) {
    // Screen y grows downwards: dragging up (dy < 0) turns the scene up, so the eye goes down.
    camera_ = orbit(camera_, -dx * kDragDegreesPerPixel, dy * kDragDegreesPerPixel, vertical_);
}

void CameraController::wheel(int notches) {
    for (int i = 0; i < std::abs(notches); ++i) move(notches > 0 ? CameraMove::DollyIn : CameraMove::DollyOut);
}

void CameraController::set_home(const CameraSpec& home) {
    bool changed = home.eye != home_.eye || home.look_at != home_.look_at || home.up != home_.up ||
                   home.fov_deg != home_.fov_deg;
    if (!changed) return;
    *this = CameraController(home);
}

}  // namespace lancer::view

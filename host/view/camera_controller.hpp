#pragma once
// The viewer's camera moves, as pure functions (a camera and a move in, the new camera out) and a
// small controller that holds the scene file's camera for reset. No window: every move is
// unit-tested, and "the camera after N key presses" is something a test can compute and render
// with `lancer render`.
//
// Step sizes are relative to the scene, so a key does the same thing in any scene. d is the
// eye–look_at distance, `vertical` the scene file's up vector:
//   arrows    eye and look_at move together by kMoveFraction · d along the camera's unit right
//             or up vector (the view direction and d do not change, so N steps move N · 0.05 · d)
//   q, d      the eye circles look_at by kOrbitDegrees about the vertical line through look_at
//             (a turntable): q to the camera's left, d to its right
//   drag      the same turntable horizontally, and vertically about the camera's right axis
//             through look_at, kDragDegreesPerPixel per pixel
//   w, x      roll by kRollDegrees about the view direction, anticlockwise / clockwise as the
//             camera sees it (the picture turns the other way)
//   +, -      dolly: d becomes d · kDollyFactor (in) or d / kDollyFactor (out); look_at stays;
//   wheel     one step per notch
// Orbits turn the up vector with the eye, and turns about the vertical or about the camera's own
// right axis never change the angle between the camera's right vector and the vertical: roll
// changes only with w and x. After every move, up is made unit length and perpendicular to the
// view direction again, so rounding never accumulates into shear or a slow roll.
#include "scene/scene.hpp"

namespace lancer::view {

constexpr double kMoveFraction = 0.05;
constexpr double kOrbitDegrees = 5.0;
constexpr double kRollDegrees = 5.0;
constexpr double kDollyFactor = 0.9;
constexpr double kDragDegreesPerPixel = 0.3;

enum class CameraMove {
    Right, Left, Up, Down,  // arrows
    OrbitLeft, OrbitRight,  // q, d
    RollLeft, RollRight,    // w, x
    DollyIn, DollyOut,      // +, -, the wheel
};

// The camera after one step of `move`. The result is always a valid camera (eye distinct from
// look_at, up unit length and perpendicular to the view).
CameraSpec apply_move(const CameraSpec& camera, CameraMove move, const dvec3& vertical);

// The eye circles look_at: by `right_deg` about the vertical line through look_at (positive:
// to the camera's right) and by `up_deg` about the camera's right axis (positive: upwards).
CameraSpec orbit(const CameraSpec& camera, double right_deg, double up_deg, const dvec3& vertical);

// `camera` with up unit length and perpendicular to the view direction: the same picture, since
// only that part of up matters. Throws UserError like make_camera_basis for a degenerate camera.
CameraSpec orthonormalize(const CameraSpec& camera);

// Unit vectors of the camera's picture plane (left-handed, as make_camera_basis builds them).
dvec3 camera_right(const CameraSpec& camera);
dvec3 camera_up(const CameraSpec& camera);

// Degrees between the camera's right vector and the plane perpendicular to `vertical`: 0 for an
// unrolled camera. What "no creeping roll" means, measurably.
double roll_degrees(const CameraSpec& camera, const dvec3& vertical);

// The viewer's camera: the scene file's camera (for reset) and the current one.
class CameraController {
public:
    explicit CameraController(const CameraSpec& home);

    const CameraSpec& camera() const { return camera_; }
    const CameraSpec& home() const { return home_; }

    void move(CameraMove m) { camera_ = apply_move(camera_, m, vertical_); }
    // A mouse drag by (dx, dy) pixels, screen y down: the scene follows the mouse (dragging right
    // turns it to the right, so the eye goes left; dragging up turns it up, so the eye goes down).
    void drag(double dx, double dy);
    // Wheel notches: positive (away from the user) dollies in.
    void wheel(int notches);
    void reset() { camera_ = home_; }
    // A reloaded scene file: a changed [camera] becomes the new home and the view jumps to it;
    // an unchanged one keeps the user's view.
    void set_home(const CameraSpec& home);

private:
    CameraSpec home_;  // as the file gives it
    CameraSpec camera_;
    dvec3 vertical_;
};

}  // namespace lancer::view

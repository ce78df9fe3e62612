#pragma once
// The sequences the viewer records with `f` and `l`, built from the current view as animated
// scenes of the animation model (scene/animation.hpp), so each frame is exactly what
// `lancer render` makes of the same [animation] table.
#include <string>

#include "scene/animation.hpp"

namespace lancer::view {

constexpr int kRecordFrames = 120;  // 4 s at 30 fps, as scenes/orbit.toml
constexpr double kRecordFps = 30.0;

// `f`: the camera circles the vertical line through look_at once, starting at the current eye
// (the [animation.camera_orbit] defaults: radius, height and start angle from the eye). Like
// every camera orbit it circles the y axis with up = [0, 1, 0], so a roll or tilt of the current
// view's up vector is not recorded. Cyclic, so the video loops. Throws UserError when the eye
// is straight above or below look_at (there is no circle).
Scene orbit_recording(const Scene& scene, const CameraSpec& camera, int frames);

// `l`: the first light circles the vertical line through look_at once, the camera stays where it
// is. Throws UserError when the scene has no light, or the light is on that line.
Scene light_recording(const Scene& scene, const CameraSpec& camera, int frames);

// One line describing a recording's animation, in the terms of docs/scene-format.md, e.g.
// "camera_orbit center [0, 0.9, 0], radius 9, height 2.3, start_angle -90, 120 frames, cyclic".
std::string describe_recording(const Animation& animation);

// The first of DIR/STEM-KIND-1, -2, ... that does not exist: recordings never overwrite.
std::string next_recording_name(const std::string& dir, const std::string& stem, const std::string& kind);

}  // namespace lancer::view

#pragma once
// Animated scenes: what moves over an animation's clock, and the pure function that turns an
// animated scene into the static Scene of one moment. Renderers only ever see static scenes.
//
// The clock runs from 0 to 1 over the animation, as POV-Ray's `clock`: frame k of N is at
// time k / (N - 1), or k / N when the animation is cyclic (POV-Ray's +KC), so that the frame
// after the last would be frame 0 again and is left out.
#include <cstddef>
#include <optional>
#include <vector>

#include "scene/scene.hpp"

namespace lancer {

constexpr int kMaxFrames = 1'000'000;
constexpr double kMinFps = 0.01, kMaxFps = 1000.0;  // what ffmpeg encodes faithfully in every format

enum class Interpolation {
    Linear,  // straight from key to key
    Smooth,  // a Catmull-Rom spline through the keys; at rest at the ends unless cyclic
};

// A circle around the vertical line through `center`. At clock time t the angle (degrees) is
// a = start_angle + 360 * turns * t and the point is center + (cos a * radius, height, sin a * radius),
// the original project's formula. Positive turns go from +x toward +z: anticlockwise seen from above.
struct Orbit {
    dvec3 center{0.0};
    double radius = 1.0;
    double height = 0.0;
    double start_angle_deg = 0.0;
    double turns = 1.0;

    dvec3 position_at(double time) const;
};

// One vec3 property over time: values at strictly increasing times in [0, 1] ([0, 1) when the
// animation is cyclic, where time 1 is time 0 again).
struct Track {
    std::vector<double> times;
    std::vector<dvec3> values;
    Interpolation interpolation = Interpolation::Linear;
};

// The track's value at `time`. Outside its keys a track holds its first or last value; in a
// cyclic animation it wraps around instead, from the last key back to the first.
dvec3 sample(const Track& track, double time, bool cyclic);

struct LightOrbit {
    std::size_t light;  // index into Scene::lights
    Orbit orbit;        // moves the light's position
};

struct LightKeys {
    std::size_t light;
    std::optional<Track> position;
    std::optional<Track> color;  // clamped at 0: a spline may overshoot below black
};

struct ObjectKeys {
    std::size_t object;     // index into Scene::objects
    std::size_t count = 1;  // objects [object, object + count): a group's members
    Track translate;        // added to the objects' geometry as the file gives it
};

struct Animation {
    int frames = 1;
    double fps = 30.0;
    bool cyclic = false;
    std::optional<Orbit> camera_orbit;  // the eye circles orbit.center and looks at it
    std::vector<LightOrbit> light_orbits;
    std::vector<LightKeys> light_keys;
    std::vector<ObjectKeys> object_keys;
};

// Clock time of a frame (0-based). Any integer is accepted: frame `frames` of a cyclic
// animation is at time 1, which scene_at() treats as time 0.
double frame_time(const Animation& animation, int frame);

// The static scene at clock time `time`: the scene with every animated property evaluated and
// no animation left. A scene without animation is returned as it is. The camera basis is
// rebuilt from eye, look_at and up for every render, so an orbiting camera's up vector is
// re-derived for each frame and the picture never shears.
Scene scene_at(const Scene& scene, double time);

// Moves a shape by `offset` (every shape family has to say how).
void translate(Shape& shape, const dvec3& offset);

}  // namespace lancer

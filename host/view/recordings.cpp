#include "view/recordings.hpp"

#include <cmath>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

namespace lancer::view {
namespace {

// The orbit through `point` around the vertical line through `center`, as the [animation]
// parser's defaults make it (the same expressions, so the same bits): radius, height and start
// angle from the point.
Orbit orbit_through(const dvec3& center, const dvec3& point) {
    dvec3 d = point - center;
    Orbit o;
    o.center = center;
    o.radius = std::hypot(d.x, d.z);
    o.height = d.y;
    o.start_angle_deg = o.radius > 1e-12 ? std::atan2(d.z, d.x) * 180.0 / M_PI : 0.0;
    o.turns = 1.0;
    return o;
}

// The parser's limits: a point on the axis has no circle, and a camera that looks (almost)
// straight down or up has no basis with the vertical as up.
bool on_axis(const Orbit& o) { return !(o.radius > 1e-12); }
bool too_steep(const Orbit& o) { return o.radius / std::hypot(o.radius, o.height) < 1e-5; }

Animation cyclic_animation(int frames) {
    Animation a;
    a.frames = frames;
    a.fps = kRecordFps;
    a.cyclic = true;
    return a;
}

std::string short_vec(const dvec3& v) { return fmt::format("[{:g}, {:g}, {:g}]", v.x, v.y, v.z); }

std::string orbit_text(const Orbit& o) {
    return fmt::format("center {}, radius {:g}, height {:g}, start_angle {:g}", short_vec(o.center), o.radius, o.height,
                       o.start_angle_deg);
}

}  // namespace

Scene orbit_recording(const Scene& scene, const CameraSpec& camera, int frames) {
    Orbit orbit = orbit_through(camera.look_at, camera.eye);
    if (on_axis(orbit) || too_steep(orbit))
        throw UserError("cannot record an orbit: the eye is straight above or below look_at (move it sideways first)");
    Scene s = scene;
    s.camera = camera;
    s.camera.up = dvec3(0.0, 1.0, 0.0);  // camera orbits circle the y axis (docs/scene-format.md)
    Animation a = cyclic_animation(frames);
    a.camera_orbit = orbit;
    s.animation = std::make_shared<const Animation>(std::move(a));
    return s;
}

Scene light_recording(const Scene& scene, const CameraSpec& camera, int frames) {
    if (scene.lights.empty()) throw UserError("cannot record the moving light: the scene has no [[light]]");
    Orbit orbit = orbit_through(camera.look_at, scene.lights[0].position);
    if (on_axis(orbit))
        throw UserError("cannot record the moving light: the first light is straight above or below look_at, "
                        "so circling it would not move it");
    Scene s = scene;
    s.camera = camera;
    Animation a = cyclic_animation(frames);
    a.light_orbits.push_back({0, orbit});
    s.animation = std::make_shared<const Animation>(std::move(a));
    return s;
}

std::string describe_recording(const Animation& a) {
    std::string what;
    if (a.camera_orbit) what = "camera_orbit " + orbit_text(*a.camera_orbit);
    for (const LightOrbit& l : a.light_orbits)
        what += (what.empty() ? "" : "; ") + fmt::format("light_orbit light {}, {}", l.light, orbit_text(l.orbit));
    return fmt::format("{}, {} frames at {:g} fps{}", what, a.frames, a.fps, a.cyclic ? ", cyclic" : "");
}

std::string next_recording_name(const std::string& dir, const std::string& stem, const std::string& kind) {
    namespace fs = std::filesystem;
    for (int n = 1;; ++n) {
        fs::path p = fs::path(dir) / fmt::format("{}-{}-{}", stem, kind, n);
        std::error_code ec;
        if (!fs::exists(p, ec) && !fs::exists(p.string() + ".mp4", ec)) return p.string();
    }
}

}  // namespace lancer::view

#pragma once
// The stage on which twin surfaces are compared (an exact surface against its analytic or
// other exact twin): camera, light, floor and one material "m"; the text ends inside an
// [[object]] with its material set, so a test appends the object's type and keys.
#include <string>

namespace lancer::test {

inline constexpr const char* kTwinStage = R"(
    [render]
    width = 120
    height = 90
    samples = 2
    [camera]
    eye = [1.5, 2.5, -4]
    look_at = [0, 0, 0]
    fov = 45
    [[light]]
    position = [-4, 6, -5]
    [material.m]
    color = [0.8, 0.5, 0.2]
    specular = 0.6
    shininess = 30
    [[object]]
    type = "plane"
    point = [0, -1.5, 0]
    normal = [0, 1, 0]
    [[object]]
    material = "m"
)";

// kTwinStage seen by a camera of the test's own (eye and look_at as TOML vectors, fov in degrees).
inline std::string twin_stage(const std::string& eye, const std::string& look_at, double fov) {
    std::string text = kTwinStage;
    auto set = [&](const std::string& from, const std::string& to) { text.replace(text.find(from), from.size(), to); };
    set("eye = [1.5, 2.5, -4]", "eye = " + eye);
    set("look_at = [0, 0, 0]", "look_at = " + look_at);
    set("fov = 45", "fov = " + std::to_string(fov));
    return text;
}

// Glass over a checkered floor, six levels of rays deep: the text ends inside an [[object]] of
// material "glass", so a test appends the solid's type and keys (both backends then compared).
inline constexpr const char* kGlassStage = R"(
    [render]
    width = 120
    height = 90
    samples = 2
    max_depth = 6
    [camera]
    eye = [0.5, 2.2, -4.5]
    look_at = [0, -0.2, 0]
    fov = 45
    [[light]]
    position = [-4, 6, -5]
    [material.floor]
    checker = { colors = [[0.9, 0.9, 0.9], [0.2, 0.3, 0.6]], size = 0.5 }
    [material.glass]
    color = [0, 0, 0]
    ambient = 0
    diffuse = 0
    transmission = [0.9, 0.95, 0.9]
    ior = 1.5
    specular = 0.8
    shininess = 200
    [[object]]
    type = "plane"
    point = [0, -1.2, 0]
    normal = [0, 1, 0]
    material = "floor"
    [[object]]
    material = "glass"
)";

}  // namespace lancer::test

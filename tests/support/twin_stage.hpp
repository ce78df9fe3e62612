#pragma once
// The stage on which twin surfaces are compared (an exact surface against its analytic or
// other exact twin): camera, light, floor and one material "m"; the text ends inside an
// [[object]] with its material set, so a test appends the object's type and keys.
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

}  // namespace lancer::test

#pragma once
// Pieces of small scenes for the tests of how the GPU's packer lays out primitives
// (family_order_test, family_boxes_test): only the objects matter to them, not the picture.
#include <string>

#include <fmt/format.h>

namespace lancer::test {

// A camera and the material every object uses ("m").
inline const std::string kPackingCameraAndMaterial = R"(
    [camera]
    eye = [0, 1, -6]
    look_at = [0, 0, 0]
    [material.m]
    color = [0.8, 0.5, 0.2]
)";

// A sphere object of material "m" centred at (x, y, 0).
inline std::string sphere_object(double x, double y, double radius) {
    return fmt::format("[[object]]\ntype = \"sphere\"\ncenter = [{}, {}, 0]\nradius = {}\nmaterial = \"m\"\n", x, y, radius);
}

// A square rectangle of material "m" at y = -1 under the objects, from -half to half in x and z.
inline std::string floor_rectangle(double half) {
    return fmt::format("[[object]]\ntype = \"rectangle\"\ncorner = [{0}, -1, {0}]\nedge_u = [{1}, 0, 0]\n"
                       "edge_v = [0, 0, {1}]\nmaterial = \"m\"\n",
                       -half, 2 * half);
}

}  // namespace lancer::test

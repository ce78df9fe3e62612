// POV-Ray's superellipsoid and blob (scene/parse_implicit_solids.cpp), against the shapes they
// must be: the superellipsoid with e = n = 1 is the sphere, with e = n = 0.001 the cube to within
// 0.06% of its size; a blob of one component is the sphere where its field is the threshold.
// Both backends, under the image tests' metric.
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "support/twin_stage.hpp"

namespace lancer {
namespace {

void expect_twins(const std::string& name, const std::string& shape, const std::string& reference) {
    const Scene a = test::scene_from_text(std::string(test::kTwinStage) + shape);
    const Scene b = test::scene_from_text(std::string(test::kTwinStage) + reference);
    for (test::Backend backend : {test::Backend::Gpu, test::Backend::Cpu})
        test::expect_same_picture(name + "-" + test::backend_name(backend), to_srgb8(test::render_on(backend, a)),
                                  to_srgb8(test::render_on(backend, b)));
}

TEST(Superellipsoid, OneOneIsTheSphere) {
    expect_twins("superellipsoid-sphere", "type = \"superellipsoid\"\ne = 1\nn = 1\ntransform = { rotate = [10, 30, 0] }\n",
                 "type = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\n");
}

// Exponents of 2000 (|x|^2000 + |y|^2000 + |z|^2000 = 1, the smallest e and n lancer takes): the
// faces are flat, without holes, and the edges and corners recede 3.5e-4 and 5.5e-4 of the size
// from the box's, which at half the twins' size moves a pixel's sample across an edge in under
// 0.1% of the pixels.
TEST(Superellipsoid, SmallExponentsAreTheCube) {
    const std::string turn = "transform = { scale = 0.5, rotate = [10, 30, 0] }\n";
    expect_twins("superellipsoid-cube", "type = \"superellipsoid\"\ne = 0.001\nn = 0.001\n" + turn,
                 "type = \"box\"\nmin = [-1, -1, -1]\nmax = [1, 1, 1]\n" + turn);
}

// Mixed exponents are not polynomials: the CPU reference's interval Newton and the GPU's search
// still agree (e = 0.3, n = 1.7: a pinched, rounded block).
TEST(Superellipsoid, MixedExponentsRenderAsTheReferenceDoes) {
    const Scene scene = test::scene_from_text(std::string(test::kTwinStage) +
                                              "type = \"superellipsoid\"\ne = 0.3\nn = 1.7\n"
                                              "transform = { rotate = [10, 30, 0] }\n");
    test::expect_same_picture("superellipsoid-mixed", to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                              to_srgb8(test::render_on(test::Backend::Cpu, scene)));
}

// strength (1 - d^2 / R^2)^2 = threshold at d = R sqrt(1 - sqrt(threshold / strength)).
TEST(Blob, OneSphereComponentIsTheSphereOfItsThreshold) {
    const double radius = 2.0, strength = 1.5, threshold = 0.6;
    const double d = radius * std::sqrt(1.0 - std::sqrt(threshold / strength));
    expect_twins("blob-sphere",
                 fmt::format("type = \"blob\"\nthreshold = {}\nspheres = [{{ center = [0.1, 0.2, 0], radius = {}, "
                             "strength = {} }}]\n",
                             threshold, radius, strength),
                 fmt::format("type = \"sphere\"\ncenter = [0.1, 0.2, 0]\nradius = {:.17g}\n", d));
}

// A cylinder component is the capsule (round ends) at the same distance from its segment: here
// against the union of a cylinder and two spheres, its exact shape.
TEST(Blob, OneCylinderComponentIsItsCapsule) {
    const double radius = 1.0, strength = 1.0, threshold = 0.25;
    const double d = radius * std::sqrt(1.0 - std::sqrt(threshold / strength));
    const std::string capsule = fmt::format(
        "type = \"group\"\nobjects = [{{ type = \"cylinder\", base_point = [-0.8, 0, 0], cap_point = [0.8, 0, 0], "
        "radius = {0:.17g} }}, {{ type = \"sphere\", center = [-0.8, 0, 0], radius = {0:.17g} }}, {{ type = "
        "\"sphere\", center = [0.8, 0, 0], radius = {0:.17g} }}]\n",
        d);
    expect_twins("blob-capsule",
                 fmt::format("type = \"blob\"\nthreshold = {}\ncylinders = [{{ base_point = [-0.8, 0, 0], cap_point = [0.8, 0, 0], "
                             "radius = {}, strength = {} }}]\n",
                             threshold, radius, strength),
                 capsule);
}

}  // namespace
}  // namespace lancer

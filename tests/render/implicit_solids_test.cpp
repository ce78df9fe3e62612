// POV-Ray's superellipsoid (a shape of its own, scene/parse_superellipsoid.cpp,
// shaders/shapes/superellipsoid.glsl, cpu/shapes/superellipsoid.cpp) and
// blob (a shape of its own, scene/parse_blob.cpp, shaders/shapes/blob.glsl, cpu/shapes/blob.cpp),
// against the shapes they must be: the superellipsoid with e = n = 1 is the sphere, with
// e = n = 0.001 the cube to within 0.06% of its size; a blob of one component is the sphere where
// its field is the threshold, of one cylinder its capsule. Then the blob's GPU code against the
// CPU reference where there is no twin: rays through more components than one of the GPU's
// windows holds, a negative component under a stretch, CSG, glass, hundreds of components. Both
// backends, under the image tests' metric.
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

// Mixed exponents (e = 0.3, n = 1.7: a pinched, rounded block): the GPU's Newton search in float
// and the CPU reference's, bracketed in double, agree.
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

// The GPU against the CPU reference on one scene.
Rgb8Image expect_backends_agree(const std::string& name, const Scene& scene) {
    const Rgb8Image gpu = to_srgb8(test::render_on(test::Backend::Gpu, scene));
    test::expect_same_picture(name, gpu, to_srgb8(test::render_on(test::Backend::Cpu, scene)));
    return gpu;
}


// A row of 60 sphere components along z, 0.15 apart, wriggling a little in x: the first 37 so
// weak that their fields never reach the threshold (a fog of components that a ray crosses
// without a hit), then within 6 steps as strong as a solid tube to the row's end. Seen along the
// row, a ray that meets the tube has passed through the supports of some 35 components first,
// more than the GPU's window of BLOB_MAX_OVERLAP = 16 holds, so the tube is found only where the
// search goes on to the next windows (shaders/shapes/blob.glsl; with a search that stops after
// the first window, the GPU draws nothing there). Radius 0.3: each component meets the 6 nearest
// (a few); 0.59: the 14 nearest (its reader allows 15), so that a point lies in up to 8 supports.
std::string row(double radius) {
    return fmt::format("type = \"blob\"\nthreshold = 0.5\nspheres = [{{ repeat = {{ i = [0, 59] }}, "
                       "center = [\"0.1 * sin(i / 4)\", 0, \"0.15 * i\"], radius = {}, "
                       "strength = \"0.03 + 0.8 * min(1, max(0, (i - 36) / 6))\" }}]\n",
                       radius);
}

// End-on, the tube's end is all there is to see, behind the fog. At least 2% of the pixels must
// show it (against the stage with a sphere out of sight), so that the comparison cannot pass on
// two pictures without it.
TEST(Blob, RaysThroughMoreComponentsThanAWindowEndOn) {
    const std::string end_on = test::twin_stage("[0.05, 0.15, -2]", "[0, 0, 6]", 10);
    const Rgb8Image empty = to_srgb8(test::render_on(
        test::Backend::Gpu, test::scene_from_text(end_on + "type = \"sphere\"\ncenter = [0, 50, 0]\nradius = 0.1\n")));
    for (double radius : {0.3, 0.59}) {
        const std::string name = fmt::format("blob-row-end-on-{}", radius);
        const Rgb8Image gpu = expect_backends_agree(name, test::scene_from_text(end_on + row(radius)));
        EXPECT_GT(compare_images(gpu, empty, 4).fraction_over, 0.02) << name << ": the tube is not seen";
    }
}

// From the side: looking along the row at a glancing angle of 6 degrees (rays cross 20 to 30
// components of the fog before the tube; a search that stops after the first window loses part
// of the tube), and across it.
TEST(Blob, RaysThroughMoreComponentsThanAWindowFromTheSide) {
    for (double radius : {0.3, 0.59}) {
        expect_backends_agree(fmt::format("blob-row-glancing-{}", radius),
                              test::scene_from_text(test::twin_stage("[0.8, 0.4, -1.5]", "[0, 0, 7.2]", 14) + row(radius)));
        expect_backends_agree(fmt::format("blob-row-across-{}", radius),
                              test::scene_from_text(test::twin_stage("[4, 1, 4.5]", "[0, 0, 5]", 30) + row(radius)));
    }
}

// A cylinder component seen from 2000 units away through a narrow lens: where the ray enters and
// leaves its support must be found from the ray's point nearest the component, not from its
// origin (in float, the quadratic of the distance to the axis from 2000 units away cancels to
// noise: stretches that reach outside the support, where q^2 adds a field that is not there, and
// specks of false hits over the capsule, 1% of the pixels, before that was fixed).
TEST(Blob, CylinderComponentSeenFromFarOff) {
    expect_backends_agree("blob-cylinder-far-off", test::scene_from_text(R"(
        [render]
        width = 120
        height = 90
        samples = 2
        [camera]
        eye = [1200, 900, -1300]
        look_at = [0, 0, 0]
        fov = 0.12
        [[light]]
        position = [-4, 6, -5]
        [[object]]
        type = "blob"
        threshold = 0.5
        cylinders = [{ base_point = [-0.6, -0.2, 0], cap_point = [0.6, 0.3, 0.2], radius = 0.5, strength = 1 }]
    )"));
}

// A negative component biting into two spheres and a cylinder, under a stretch (not a
// similarity: both renderers trace it in its own coordinates). The bite must show.
TEST(Blob, NegativeComponentUnderAStretch) {
    const auto with = [](const std::string& negative) {
        return test::scene_from_text(
            std::string(test::kTwinStage) +
            "type = \"blob\"\nthreshold = 0.5\n"
            "spheres = [{ center = [-0.5, 0, 0], radius = 1, strength = 1 }, "
            "{ center = [0.6, 0.1, 0], radius = 0.9, strength = 1 }" +
            negative +
            "]\ncylinders = [{ base_point = [-0.2, -0.6, 0], cap_point = [0.3, 0.7, 0.6], radius = 0.45, "
            "strength = 0.8 }]\n"
            "transform = { scale = [1.6, 0.7, 1], rotate = [10, 20, 0] }\n");
    };
    const Rgb8Image bitten =
        expect_backends_agree("blob-negative-stretched", with(", { center = [0.7, 0.55, -0.2], radius = 0.6, strength = -1.5 }"));
    EXPECT_GT(compare_images(bitten, to_srgb8(test::render_on(test::Backend::Gpu, with(""))), 4).fraction_over, 0.01)
        << "the negative component changes nothing";
}

// Two spheres and a cylinder, as a CSG operand: cut out of a box, and cut by a sphere.
const char* const kOperand =
    "{ type = \"blob\", threshold = 0.5, spheres = [{ center = [-0.6, 0.2, -0.6], radius = 1, strength = 1 }, "
    "{ center = [0.5, 0.3, -0.7], radius = 0.9, strength = 1 }], cylinders = [{ base_point = [0, -0.5, -1.2], "
    "cap_point = [0.2, 1.2, 0.4], radius = 0.5, strength = 0.9 }] }";

TEST(Blob, BoxLessABlob) {
    expect_backends_agree("blob-csg-difference",
                          test::scene_from_text(std::string(test::kTwinStage) + "type = \"difference\"\nobjects = [" +
                                                "{ type = \"box\", min = [-1, -1, -1], max = [1, 1, 1] }, " + kOperand + "]\n"));
}

// Two lobes apart, cut out of a bar seen along it: rays through both lobes leave the bar between
// them, which a CSG walk taking the blob's inside as one interval (a convex solid's) would cut.
TEST(Blob, CsgWalksAcrossItsSeparateLobes) {
    expect_backends_agree(
        "blob-csg-lobes",
        test::scene_from_text(test::twin_stage("[4.5, 1.2, -1.6]", "[0, 0, 0]", 40) +
                              "type = \"difference\"\nobjects = [{ type = \"box\", min = [-1.8, -0.45, -0.45], max = "
                              "[1.8, 0.45, 0.45] }, { type = \"blob\", threshold = 0.5, spheres = [{ center = [-0.9, 0.2, "
                              "-0.2], radius = 0.8, strength = 1 }, { center = [0.9, 0.2, -0.2], radius = 0.8, strength = 1 "
                              "}] }]\n"));
}

TEST(Blob, BlobCutByASphere) {
    expect_backends_agree("blob-csg-intersection",
                          test::scene_from_text(std::string(test::kTwinStage) + "type = \"intersection\"\nobjects = [" + kOperand +
                                                ", { type = \"sphere\", center = [0, 0.2, -0.5], radius = 0.95 }]\n"));
}

// Glass: a drop of two spheres, a cylinder through their neck and a negative component, over a
// checkered floor, which it bends through up to 6 levels of rays (entering, reflected inside,
// leaving). The backends' pictures part only where a ray that has been bent several times lands
// within rounding of a checker edge, and such pixels grow with finer checkers and deeper rays:
// 2 of these 10,800 (0.02%); with checkers of 0.4 and 8 levels, 17 (0.16%, over the metric's 0.1%).
TEST(Blob, GlassBendsLightAsTheReferenceDoes) {
    const Scene scene = test::scene_from_text(std::string(test::kGlassStage) + R"(
        type = "blob"
        threshold = 0.5
        spheres = [{ center = [-0.7, 0, 0], radius = 1.1, strength = 1 }, { center = [0.7, 0.1, 0.2], radius = 1, strength = 1 },
                   { center = [0, 0.5, -0.6], radius = 0.5, strength = -0.8 }]
        cylinders = [{ base_point = [0, -0.8, 0.8], cap_point = [0, 0.9, -0.2], radius = 0.5, strength = 0.8 }]
    )");
    expect_backends_agree("blob-glass", scene);
}

// 320 components from one repeat: spheres on a ball's Fibonacci lattice (golden-angle turns,
// even steps in y), their strengths waving with i, each meeting about 8 others: a knobbly shell
// with a hollow inside, where a ray through it crosses the components of two sides.
TEST(Blob, HundredsOfComponentsFromARepeat) {
    const char* const y = "(1 - (2 * i + 1) / 320)";
    const std::string ring = fmt::format("1.1 * sqrt(1 - {}^2)", y);
    expect_backends_agree(
        "blob-fibonacci-ball",
        test::scene_from_text(std::string(test::kTwinStage) +
                              fmt::format("type = \"blob\"\nthreshold = 0.45\nspheres = [{{ repeat = {{ i = [0, 319] }}, "
                                          "center = [\"{0} * cos(2.39996 * i)\", \"1.1 * {1}\", \"{0} * sin(2.39996 * i)\"], "
                                          "radius = 0.2, strength = \"1 + 0.5 * sin(i / 7)\" }}]\n"
                                          "transform = {{ rotate = [20, 10, 0] }}\n",
                                          ring, y)));
}

}  // namespace
}  // namespace lancer

// Transforms on every object (docs/scene-format.md, "Transforms"), on both backends: an
// ellipsoid against its implicit quadric; a scene turned as a whole against the camera turned
// the other way (turned boxes, stretched discs, checkers and patterns riding on their objects);
// a checker that travels with its object through an animation.
#include <cmath>
#include <regex>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cpu/cpu_renderer.hpp"
#include "scene/animation.hpp"
#include "support/test_support.hpp"
#include "support/twin_stage.hpp"

namespace lancer {
namespace {

void expect_close(const std::string& label, const Rgb8Image& image, const Rgb8Image& reference) {
    const ImageDiff d = compare_images(image, reference, 4);
    EXPECT_GE(d.psnr_db, 40.0) << label;
    EXPECT_LE(d.fraction_over, 0.001) << label;
    if (d.fraction_over > 0.0) test::save_comparison(label, image, reference);
}

// A sphere stretched, turned and moved is the ellipsoid (x/a)^2 + (y/b)^2 + (z/c)^2 = 1 under the
// same turn and move: the implicit surface's certified roots are the reference.
TEST(Transforms, AStretchedSphereIsItsImplicitEllipsoid) {
    const std::string move = "transform = [ { scale = [1.4, 0.6, 0.9] }, { rotate = [20, 30, 25], translate = [0.2, 0.1, 0] } ]";
    const std::string turn = "transform = { rotate = [20, 30, 25], translate = [0.2, 0.1, 0] }";
    const Scene sphere = test::scene_from_text(std::string(test::kTwinStage) + "type = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\n" + move);
    const Scene implicit = test::scene_from_text(std::string(test::kTwinStage) + R"(
        type = "implicit"
        function = "(x / 1.4)^2 + (y / 0.6)^2 + (z / 0.9)^2 - 1"
        box = { min = [-1.5, -0.7, -1], max = [1.5, 0.7, 1] }
        )" + turn);
    const Rgb8Image reference = to_srgb8(CpuRenderer().render(implicit, {}));
    for (test::Backend backend : {test::Backend::Cpu, test::Backend::Gpu})
        expect_close(fmt::format("ellipsoid-{}", test::backend_name(backend)), to_srgb8(test::render_on(backend, sphere)), reference);
}

// The objects of a scene, each given its own transform (`own`) and then `turn`.
std::string turned_objects(const std::string& turn) {
    auto object = [&](const std::string& body, const std::string& own) {
        return fmt::format("[[object]]\n{}\ntransform = [ {}{} ]\n", body, own, turn.empty() ? "" : ", " + turn);
    };
    return object("type = \"plane\"\nnormal = [0, 1, 0]\npoint = [0, -1, 0]\nmaterial = \"floor\"", "{ rotate = [0, 10, 0] }") +
           object("type = \"box\"\nmin = [-0.6, -0.6, -0.6]\nmax = [0.6, 0.6, 0.6]\nmaterial = \"squares\"",
                  "{ rotate = [25, 35, 10], translate = [-1.2, -0.1, 0.4] }") +
           object("type = \"sphere\"\ncenter = [0, 0, 0]\nradius = 0.7\nmaterial = \"marble\"",
                  "{ scale = [1.3, 0.7, 0.9], translate = [1.1, -0.3, -0.3] }") +
           object("type = \"disc\"\ncenter = [0, 0, 0]\nnormal = [0, 0, -1]\nradius = 0.5\nhole_radius = 0.2\nmaterial = \"squares\"",
                  "{ scale = [1.6, 0.8, 1], translate = [0.3, 1.1, 1.2] }") +
           object("type = \"rectangle\"\ncorner = [-0.5, 0, -0.5]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]\nmaterial = \"squares\"",
                  "{ matrix = [1, 0, 0, 0.4, 1, 0, 0, 0, 1, 0, 0, 0] }, { translate = [0.2, -0.99, -1.4] }");
}

// grouped: the objects in one group that takes the turn, instead of each taking it.
std::string turned_scene(double degrees, bool grouped = false) {
    const double a = degrees * M_PI / 180.0;
    // POV-Ray's rotate about y: (x, z) -> (x cos a + z sin a, -x sin a + z cos a).
    auto turned = [&](double x, double y, double z) {
        return fmt::format("[{}, {}, {}]", x * std::cos(a) + z * std::sin(a), y, -x * std::sin(a) + z * std::cos(a));
    };
    const std::string turn = degrees == 0.0 ? "" : fmt::format("{{ rotate = [0, {}, 0] }}", degrees);
    return fmt::format(R"(
        [render]
        width = 120
        height = 90
        samples = 2
        [camera]
        eye = {}
        look_at = {}
        fov = 50
        [[light]]
        position = {}
        [material.floor]
        checker = {{ colors = [[1, 1, 1], [0.3, 0.3, 0.3]], size = 0.5 }}
        [material.squares]
        checker = {{ colors = [[0.2, 0.3, 0.9], [0.9, 0.8, 0.2]], size = 0.2 }}
        specular = 0.5
        [material.marble]
        color = [1, 1, 1]
        specular = 0.4
        pattern = {{ type = "marble", scale = 0.4, turbulence = 1.5, colors = [[0.9, 0.9, 0.85], [0.3, 0.1, 0.1]] }}
        bump = {{ type = "noise", scale = 0.15, amount = 0.3 }}
        )",
                       turned(0.5, 2.2, -4.5), turned(0, -0.2, 0), turned(-4, 6, -5)) +
           (grouped ? fmt::format("[[object]]\ntype = \"group\"\ntransform = {}\n", turn) +
                          std::regex_replace(turned_objects(""), std::regex("\\[\\[object\\]\\]"), "[[object.objects]]")
                    : turned_objects(turn));
}

// Turning every object and light by 40 degrees about y and the camera with them shows the same
// picture: shapes kept in their own coordinates (the turned box, the stretched sphere and disc),
// shapes given their transform (the plane, the sheared rectangle), and checkers, patterns and
// bumps, which ride on their objects.
TEST(Transforms, TurningTheWholeSceneIsTurningTheCamera) {
    const Scene turned = test::scene_from_text(turned_scene(40.0));
    const Scene still = test::scene_from_text(turned_scene(0.0));
    for (test::Backend backend : {test::Backend::Cpu, test::Backend::Gpu}) {
        const std::string label = fmt::format("turned-scene-{}", test::backend_name(backend));
        expect_close(label, to_srgb8(test::render_on(backend, turned)), to_srgb8(test::render_on(backend, still)));
    }
    // And the backends agree on it.
    expect_close("turned-scene-gpu-vs-cpu", to_srgb8(test::render_on(test::Backend::Gpu, turned)),
                 to_srgb8(test::render_on(test::Backend::Cpu, turned)));
}

// POV-Ray users tilt a whole union at once: the group's turn is each member's, after its own.
TEST(Transforms, AGroupTurnsItsMembersAsOne) {
    const Scene grouped = test::scene_from_text(turned_scene(40.0, true));
    const Scene each = test::scene_from_text(turned_scene(40.0));
    ASSERT_EQ(grouped.objects.size(), each.objects.size());
    for (test::Backend backend : {test::Backend::Cpu, test::Backend::Gpu}) {
        const ImageDiff d = compare_images(to_srgb8(test::render_on(backend, grouped)), to_srgb8(test::render_on(backend, each)), 0);
        EXPECT_EQ(d.fraction_over, 0.0) << test::backend_name(backend);  // the same maps, the same picture
    }
}

// Before transforms were attached to their objects, a checker stayed in the world while its
// object moved through it: a moving checkered ball must look the same at every moment.
TEST(Transforms, ACheckerTravelsWithItsObjectThroughAnAnimation) {
    const Scene scene = test::scene_from_text(R"(
        [render]
        width = 64
        height = 48
        samples = 1
        [camera]
        eye = [0, 0, -4]
        look_at = [0, 0, 0]
        fov = 40
        [[light]]
        position = [0, 0, -10]
        [material.squares]
        checker = { colors = [[0.2, 0.3, 0.9], [0.9, 0.8, 0.2]], size = 0.25 }
        [[object]]
        type = "sphere"
        name = "ball"
        center = [0, 0, 0]
        radius = 1
        material = "squares"
        transform = { rotate = [10, 20, 0] }
        [animation]
        frames = 3
        [[animation.object]]
        object = "ball"
        keys = [{ time = 0.0, translate = [0, 0, 0] }, { time = 1.0, translate = [0.37, 0, 0] }]
    )");
    const Scene first = scene_at(scene, 0.0), last = scene_at(scene, 1.0);
    // The last frame, seen from a camera moved with the ball, is the first.
    Scene followed = last;
    followed.camera.eye.x += 0.37;
    followed.camera.look_at.x += 0.37;
    for (Light& l : followed.lights) l.position.x += 0.37;
    for (test::Backend backend : {test::Backend::Cpu, test::Backend::Gpu})
        expect_close(fmt::format("travelling-checker-{}", test::backend_name(backend)), to_srgb8(test::render_on(backend, followed)),
                     to_srgb8(test::render_on(backend, first)));
}

// A checker's own transform comes before its object's: doubled and turned a quarter about z
// (which maps the lattice onto itself with the parities swapped), it is the checker of twice
// the size with its colours swapped, on a ball turned by its own transform.
TEST(Transforms, ACheckersOwnTransformComesBeforeItsObjects) {
    const std::string stage = R"(
        [render]
        width = 64
        height = 48
        samples = 1
        [camera]
        eye = [0, 0, -4]
        look_at = [0, 0, 0]
        fov = 40
        [[light]]
        position = [0, 0, -10]
        [[object]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
        material = "squares"
        transform = { rotate = [10, 20, 0], translate = [0.1, 0, 0] }
    )";
    const Scene own = test::scene_from_text(stage + R"(
        [material.squares]
        checker = { colors = [[0.2, 0.3, 0.9], [0.9, 0.8, 0.2]], size = 0.25, transform = [{ scale = 2 }, { rotate = [0, 0, 90] }] }
    )");
    const Scene plain = test::scene_from_text(stage + R"(
        [material.squares]
        checker = { colors = [[0.9, 0.8, 0.2], [0.2, 0.3, 0.9]], size = 0.5 }
    )");
    for (test::Backend backend : {test::Backend::Cpu, test::Backend::Gpu})
        expect_close(fmt::format("checker-transform-{}", test::backend_name(backend)), to_srgb8(test::render_on(backend, own)),
                     to_srgb8(test::render_on(backend, plain)));
    // A checker's transform alone (not a lattice map) on both backends.
    const Scene turned = test::scene_from_text(stage + R"(
        [material.squares]
        checker = { colors = [[0.2, 0.3, 0.9], [0.9, 0.8, 0.2]], size = 0.25, transform = { rotate = [0, 0, 30], translate = [0.1, 0, 0] } }
    )");
    const Rgb8Image gpu = to_srgb8(test::render_on(test::Backend::Gpu, turned));
    expect_close("checker-turned-gpu-vs-cpu", gpu, to_srgb8(test::render_on(test::Backend::Cpu, turned)));
    EXPECT_GT(compare_images(gpu, to_srgb8(test::render_on(test::Backend::Gpu, own)), 4).fraction_over, 0.1);  // it did turn
}

}  // namespace
}  // namespace lancer

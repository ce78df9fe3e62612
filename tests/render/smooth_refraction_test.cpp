// Refraction along shading normals, as POV-Ray bends light: a glass ball drawn as an icosphere
// mesh shaded smooth shows the checkered wall behind it as the exact sphere does (but for its
// silhouette's facets), where the same mesh shaded flat breaks the wall into a facet's piece each.
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "image/diff.hpp"
#include "image/image.hpp"
#include "support/test_meshes.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

using test::Backend;

// The ball, of radius 1, at (0.0437, 0.0213, 0) before the wall: off the checker's axes, so that
// no ray of a symmetric pair meets a square's edge, and squares large enough that float's
// rounding of a bent ray seldom crosses one (the lens magnifies it at the rim).
std::string glass_ball_scene(const std::string& ball) {
    return fmt::format(R"([render]
width = 120
height = 90
samples = 2
max_depth = 6

[camera]
eye = [0.0437, 0.0213, -4]
look_at = [0.0437, 0.0213, 0]
fov = 36

[ambient]
color = [1, 1, 1]

[material.wall]
checker = {{ colors = [[1, 1, 1], [0.1, 0.1, 0.1]], size = 0.5 }}
ambient = 1
diffuse = 0

[material.glass]
transmission = 1
ior = 1.5
ambient = 0
diffuse = 0
specular = 0

[[object]]
type = "rectangle"
corner = [-4, -3, 2]
edge_u = [8, 0, 0]
edge_v = [0, 6, 0]
material = "wall"

[[object]]
material = "glass"
{}
)",
                       ball);
}

// The ball as the icosphere in dir/ball.obj (320 triangles with the sphere's own normals).
std::string mesh_ball(const std::string& dir, bool smooth) {
    return fmt::format("type = \"mesh\"\nfile = \"{}/ball.obj\"\nsmooth = {}\ntransform = {{ translate = [0.0437, 0.0213, 0] }}",
                       dir, smooth);
}

class SmoothRefraction : public testing::TestWithParam<Backend> {
protected:
    Rgb8Image render(const std::string& ball) {
        return to_srgb8(test::render_on(GetParam(), test::scene_from_text(glass_ball_scene(ball))));
    }
};

TEST_P(SmoothRefraction, SmoothMeshBendsLightAsTheSphereItApproximates) {
    const std::string dir = test::fresh_dir("smooth-refraction");
    test::write_file(dir + "/ball.obj", test::obj_text(test::icosphere(2)));
    const Rgb8Image sphere = render("type = \"sphere\"\ncenter = [0.0437, 0.0213, 0]\nradius = 1");
    const Rgb8Image smooth = render(mesh_ball(dir, true));
    const Rgb8Image flat = render(mesh_ball(dir, false));
    const double smooth_db = compare_images(smooth, sphere, 4).psnr_db;
    const double flat_db = compare_images(flat, sphere, 4).psnr_db;
    RecordProperty("smooth_db", std::to_string(smooth_db));
    RecordProperty("flat_db", std::to_string(flat_db));
    EXPECT_GT(smooth_db, flat_db + 3.0) << "smooth " << smooth_db << " dB, flat " << flat_db << " dB from the exact sphere";
}

INSTANTIATE_TEST_SUITE_P(Backends, SmoothRefraction, testing::Values(Backend::Cpu, Backend::Gpu),
                         [](const auto& info) { return std::string(info.param == Backend::Cpu ? "Cpu" : "Gpu"); });

TEST(SmoothRefractionBackends, Agree) {
    const std::string dir = test::fresh_dir("smooth-refraction-backends");
    test::write_file(dir + "/ball.obj", test::obj_text(test::icosphere(2)));
    const Scene scene = test::scene_from_text(glass_ball_scene(mesh_ball(dir, true)));
    test::expect_same_picture("smooth-refraction-backends", to_srgb8(test::render_on(Backend::Gpu, scene)),
                              to_srgb8(test::render_on(Backend::Cpu, scene)));
}

}  // namespace
}  // namespace lancer

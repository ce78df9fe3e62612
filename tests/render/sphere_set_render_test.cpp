// Sphere sets on both backends: a PLY point set's glass spheres (overlapping: nested media),
// coloured by the file, placed by a transform, are the same picture as the same spheres written one object each (on each backend),
// and the backends agree.
#include <random>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "image/image.hpp"
#include "scene/load_scene.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

TEST(SphereSets, AreTheirSpheresWrittenOneByOne) {
    const std::string dir = test::fresh_dir("sphere-sets");
    const std::string transform = "transform = [ { rotate = [0, 30, 10] }, { scale = 1.2 }, { translate = [0.3, 0, 0] } ]\n";
    std::string points, objects;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> at(-1.5f, 1.5f), size(0.08f, 0.35f);
    std::uniform_int_distribution<int> code(0, 3);
    const int count = 300;
    for (int i = 0; i < count; ++i) {
        const float x = at(rng), y = at(rng) * 0.5f + 0.6f, z = at(rng), r = size(rng);
        const int c = code(rng);  // four colours: the palette has four materials
        points += fmt::format("{} {} {} {} {} {} {}\n", x, y, z, r, 60 * c, 255 - 60 * c, 128);
        objects += fmt::format("[[object]]\ntype = \"sphere\"\ncenter = [{}, {}, {}]\nradius = {}\nmaterial = \"c{}\"\n{}", x, y, z, r, c,
                               transform);
    }
    test::write_file(dir + "/points.ply", fmt::format("ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\n"
                                                      "property float z\nproperty float radius\nproperty uchar red\n"
                                                      "property uchar green\nproperty uchar blue\nend_header\n{}",
                                                      count, points));
    std::string stage = R"([render]
width = 240
height = 135
samples = 3
max_depth = 3

[camera]
eye = [0, 3, -6]
look_at = [0, 0.5, 0]
fov = 50

[[light]]
position = [4, 8, -5]

[material.floor]
checker = { colors = [[0.9, 0.9, 0.9], [0.2, 0.2, 0.25]], size = 0.5 }

[material.ball]
specular = 0.6
shininess = 40
reflection = 0.25
transmission = [0.5, 0.5, 0.5]
ior = 1.4

[[object]]
type = "plane"
point = [0, -0.6, 0]
normal = [0, 1, 0]
material = "floor"
)";
    // The point colours as the loader decodes them (sRGB codes), on the ball material.
    for (int c = 0; c < 4; ++c)
        stage += fmt::format("[material.c{}]\ncolor = [{}, {}, {}]\nspecular = 0.6\nshininess = 40\nreflection = 0.25\n"
                             "transmission = [0.5, 0.5, 0.5]\nior = 1.4\n", c,
                             decode_srgb8(static_cast<std::uint8_t>(60 * c)), decode_srgb8(static_cast<std::uint8_t>(255 - 60 * c)),
                             decode_srgb8(128));
    test::write_file(dir + "/set.toml", stage + "[[object]]\ntype = \"spheres\"\nfile = \"points.ply\"\nmaterial = \"ball\"\n" + transform);
    test::write_file(dir + "/objects.toml", stage + objects);
    const Scene set = load_scene(dir + "/set.toml"), one_by_one = load_scene(dir + "/objects.toml");
    const Rgb8Image cpu_set = to_srgb8(test::render_on(test::Backend::Cpu, set));
    const Rgb8Image gpu_set = to_srgb8(test::render_on(test::Backend::Gpu, set));
    test::expect_same_picture("sphere-set-cpu", cpu_set, to_srgb8(test::render_on(test::Backend::Cpu, one_by_one)));
    test::expect_same_picture("sphere-set-gpu", gpu_set, to_srgb8(test::render_on(test::Backend::Gpu, one_by_one)));
    test::expect_same_picture("sphere-set-backends", gpu_set, cpu_set);
}

}  // namespace
}  // namespace lancer

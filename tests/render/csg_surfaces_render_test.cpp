// CSG over parametric and Bezier surfaces declared closed and a closed mesh, on both backends: an
// opaque box with a spherical cavity cut by a parametric sphere, a glass die cut from a sphere by
// a Bezier cube, and a ball with a corner cut out by a mesh cube, are the same picture as their
// twins cut by an analytic sphere and boxes (on each backend), and the backends agree.
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "image/image.hpp"
#include "support/test_meshes.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

std::string scene(const std::string& cavity, const std::string& cut, const std::string& corner) {
    return fmt::format(R"([render]
width = 200
height = 112
samples = 2
max_depth = 4

[camera]
eye = [0, 2.5, -5]
look_at = [0, 0.6, 0]
fov = 45

[[light]]
position = [-5, 8, -6]

[material.floor]
checker = {{ colors = [[0.9, 0.9, 0.9], [0.2, 0.2, 0.25]], size = 0.5 }}

[material.ivory]
color = [0.92, 0.9, 0.82]
specular = 0.5
shininess = 50

[material.red]
color = [0.85, 0.15, 0.1]

[material.glass]
transmission = [0.9, 0.9, 0.9]
ior = 1.5
specular = 0.8
shininess = 80
reflection = 0.1

[[object]]
type = "plane"
normal = [0, 1, 0]
material = "floor"

[[object]]
type = "difference"
material = "ivory"
transform = {{ rotate = [0, 30, 0], translate = [-1.1, 0.7, 0] }}
objects = [{{ type = "box", min = [-0.7, -0.7, -0.7], max = [0.7, 0.7, 0.7] }}, {}]

[[object]]
type = "intersection"
material = "glass"
transform = {{ rotate = [10, -25, 0], translate = [1.1, 0.75, 0] }}
objects = [{{ type = "sphere", center = [0, 0, 0], radius = 0.75 }}, {}]

[[object]]
type = "difference"
material = "ivory"
transform = {{ rotate = [0, -40, 0], translate = [0, 0.5, -1.6] }}
objects = [{{ type = "sphere", center = [0, 0, 0], radius = 0.5 }}, {}]
)",
                       cavity, cut, corner);
}

TEST(CsgSurfaces, AreTheSolidsTheyEnclose) {
    const std::string parametric_sphere =
        R"toml({ type = "parametric", closed = true, x = "0.6*cos(v)*cos(u)", y = "0.4 + 0.6*sin(v)", z = "-0.4 + 0.6*cos(v)*sin(u)", u = [0, "2*pi"], v = ["-pi/2", "pi/2"], material = "red" })toml";
    const std::string sphere = R"toml({ type = "sphere", center = [0, 0.4, -0.4], radius = 0.6, material = "red" })toml";
    const std::string box = R"toml({ type = "box", min = [-0.55, -0.55, -0.55], max = [0.55, 0.55, 0.55], material = "red" })toml";
    const std::string dir = test::fresh_dir("csg-surfaces");
    test::write_file(dir + "/cube.obj", test::cube_obj(glm::dvec3(0.25, 0.25, -0.25), 0.3));
    const std::string mesh = "{ type = \"mesh\", file = \"" + dir + "/cube.obj\", material = \"red\" }";
    const std::string corner = R"toml({ type = "box", min = [-0.05, -0.05, -0.55], max = [0.55, 0.55, 0.05], material = "red" })toml";
    const Scene surfaces = test::scene_from_text(scene(parametric_sphere, test::bezier_cube(glm::dvec3(0.0), 0.55, false, -1, "material = \"red\""), mesh));
    const Scene solids = test::scene_from_text(scene(sphere, box, corner));
    const Rgb8Image cpu = to_srgb8(test::render_on(test::Backend::Cpu, surfaces));
    const Rgb8Image gpu = to_srgb8(test::render_on(test::Backend::Gpu, surfaces));
    test::expect_same_picture("csg-surfaces-cpu", cpu, to_srgb8(test::render_on(test::Backend::Cpu, solids)));
    test::expect_same_picture("csg-surfaces-gpu", gpu, to_srgb8(test::render_on(test::Backend::Gpu, solids)));
    test::expect_same_picture("csg-surfaces-backends", gpu, cpu);
}

// An opaque slab with a round hole cut by a mesh ball, seen from under the slab: the floor is lit
// through the hole. Shadow rays may stop at any blocker, but a mesh leaf's walk must still find
// its nearest crossing, or the hole's walls close where they are not and the lit disc cracks.
std::string slab_with_hole(const std::string& hole) {
    return fmt::format(R"([render]
width = 160
height = 90
samples = 1

[camera]
eye = [0, 1.2, -2.5]
look_at = [0, 0, 0]
fov = 50

[[light]]
position = [0.3, 9, 0.2]

[material.floor]
color = [0.9, 0.9, 0.9]

[material.ivory]
color = [0.92, 0.9, 0.82]

[[object]]
type = "plane"
normal = [0, 1, 0]
material = "floor"

[[object]]
type = "difference"
material = "ivory"
objects = [{{ type = "box", min = [-2, 1.5, -2], max = [2, 1.7, 2] }}, {}]
)",
                       hole);
}

TEST(CsgSurfaces, MeshHoleLetsShadowRaysThrough) {
    const std::string dir = test::fresh_dir("csg-mesh-hole");
    test::write_file(dir + "/ball.obj", test::obj_text(test::icosphere(4, glm::dvec3(0.0, 1.6, 0.0), 0.7)));
    const Scene mesh = test::scene_from_text(slab_with_hole("{ type = \"mesh\", file = \"" + dir + "/ball.obj\" }"));
    test::expect_same_picture("csg-mesh-hole-backends", to_srgb8(test::render_on(test::Backend::Gpu, mesh)),
                              to_srgb8(test::render_on(test::Backend::Cpu, mesh)));
}

}  // namespace
}  // namespace lancer

// What lies around the scene. [fog], POV-Ray's constant fog: what a ray meets at distance d shows
// through exp(-d / distance) of it, the fog's colour the rest; a ray that meets nothing is all
// fog. [sky], POV-Ray's sky_sphere with gradient y: a ray that meets nothing sees the ramp at its
// direction's height, wrapped as POV-Ray's gradient. Exact on the reference, the same on the GPU,
// and their keys refused where wrong.
#include <cmath>

#include <fmt/format.h>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include "cpu/pattern.hpp"
#include "scene/camera.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

// A wall at distance 4 straight ahead, lit by its ambient term alone (ambient 1, diffuse 0):
// the pixel in the middle sees its colour c through the fog; the top row sees nothing.
const char* const kWall = R"toml(
[render]
width = 9
height = 9
samples = 1
background = [1, 0, 0]
[camera]
eye = [0, 0, -4]
look_at = [0, 0, 0]
fov = 10
[ambient]
color = [1, 1, 1]
[material.wall]
color = [0.2, 0.6, 0.4]
ambient = 1
diffuse = 0
[[object]]
type = "rectangle"
corner = [-0.1, -0.1, 0]
edge_u = [0.2, 0, 0]
edge_v = [0, 0.2, 0]
material = "wall"
[fog]
distance = 5
color = [0.5, 0.25, 1.0]
)toml";

TEST(Fog, VeilsWhatARayMeetsByItsDistance) {
    const Scene scene = test::scene_from_text(kWall);
    for (test::Backend backend : {test::Backend::Cpu, test::Backend::Gpu}) {
        const FloatImage image = test::render_on(backend, scene);
        const double through = std::exp(-4.0 / 5.0);
        const glm::dvec3 wall(0.2, 0.6, 0.4), fog(0.5, 0.25, 1.0);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(image.at(4, 4)[c], wall[c] * through + fog[c] * (1.0 - through), test::kBackendTolerance)
                << test::backend_name(backend) << " channel " << c;
            EXPECT_NEAR(image.at(4, 0)[c], fog[c], test::kBackendTolerance) << test::backend_name(backend);  // no background through it
        }
    }
}

TEST(Fog, TheGpuDrawsTheReferencesPicture) {
    Scene scene = test::shipped_scene("seed", 160, 90, 2);
    scene.fog = Fog{{0.7, 0.75, 0.8}, 12.0};
    test::expect_same_picture("fog_seed", to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                              to_srgb8(test::render_on(test::Backend::Cpu, scene)));
}

TEST(Fog, ItsKeysAreChecked) {
    const std::string camera = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n";
    test::expect_scene_error(camera + "[fog]\ndistance = 0\n", 5, 12, "fog distance must be positive, not 0");
    test::expect_scene_error(camera + "[fog]\ncolor = [1, 1, 1]\n", 4, 1, "distance");
    test::expect_scene_error(camera + "[fog]\ndistance = 3\nfog_type = 2\n", 6, 1,
                             "unknown key 'fog_type' (POV-Ray's fog_type 1 is [fog] type = \"constant\", 2 is type = \"ground\")");
    test::expect_scene_error(camera + "[fog]\ndistance = 3\noffset = 1\n", 6, 10, "offset belongs to the ground fog");
    test::expect_scene_error(camera + "[fog]\ndistance = 3\ntype = \"ground\"\naltitude = 0\n", 7, 12,
                             "fog altitude must be positive, not 0");
    test::expect_scene_error(camera + "[fog]\ndistance = 3\ntype = \"ground\"\nup = [0, 0, 0]\n", 7, 6,
                             "fog up must not be the zero vector");
    test::expect_scene_error(camera + "[fog]\ndistance = 3\ntype = \"layer\"\n", 6, 8, "unknown fog type 'layer'");
}

// POV-Ray's ground fog (fog_type 2): density 1 / (1 + Y^2) at the height Y above the offset, in
// altitudes. The camera looks level at the wall from Y = 2 (density 1/5): the wall shows through
// exp(-4 / 5 / 5); the top row looks up, out of the fog, and sees the background through what
// fog lies above (fog_depth, proved against the integral in tests/unit/fog_test.cpp).
TEST(Fog, GroundFogVeilsByTheDensityAlongTheRay) {
    std::string text = kWall;
    text += "type = \"ground\"\noffset = -1\naltitude = 0.5\n";
    const Scene scene = test::scene_from_text(text);
    const CameraSpec& cam = scene.camera;
    const CameraBasis basis = make_camera_basis(cam, 9, 9);
    const glm::dvec3 up_dir = glm::normalize(camera_ray_direction(basis, 4.5, 0.5, 9, 9));
    const double wall_through = std::exp(-4.0 / 5.0 / 5.0);
    const double sky_through = std::exp(-fog_depth(*scene.fog, cam.eye, up_dir, INFINITY) / 5.0);
    ASSERT_GT(sky_through, 0.05);  // the sky shows: the ray leaves the fog
    const glm::dvec3 wall(0.2, 0.6, 0.4), fog(0.5, 0.25, 1.0), background(1.0, 0.0, 0.0);
    for (test::Backend backend : {test::Backend::Cpu, test::Backend::Gpu}) {
        const FloatImage image = test::render_on(backend, scene);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(image.at(4, 4)[c], wall[c] * wall_through + fog[c] * (1.0 - wall_through), test::kBackendTolerance)
                << test::backend_name(backend) << " channel " << c;
            EXPECT_NEAR(image.at(4, 0)[c], background[c] * sky_through + fog[c] * (1.0 - sky_through), test::kBackendTolerance)
                << test::backend_name(backend) << " channel " << c;
        }
    }
}

TEST(Fog, TheGpuDrawsTheReferencesGroundFog) {
    Scene scene = test::shipped_scene("seed", 160, 90, 2);
    scene.fog = Fog{{0.85, 0.85, 0.9}, 6.0, Fog::Ground{{0.0, 1.0, 0.0}, 0.3, 0.5}};
    test::expect_same_picture("ground_fog_seed", to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                              to_srgb8(test::render_on(test::Backend::Cpu, scene)));
}

// A camera looking up at 30 degrees, and one looking down at 30 (the gradient wraps: -0.5 is 0.5
// up the ramp), each pixel in the middle against the ramp's value there.
TEST(Sky, RaysThatMeetNothingSeeItsRampAtTheirHeight) {
    for (const char* look : {"[0, 0.57735026918962573, 1]", "[0, -0.57735026918962573, 1]"}) {
        const Scene scene = test::scene_from_text(std::string(R"toml(
[render]
width = 9
height = 9
samples = 1
background = [1, 0, 0]
[camera]
eye = [0, 0, 0]
fov = 1
look_at = )toml") + look + R"toml(
[sky]
colors = [[0.9, 0.95, 1.0], [0.25, 0.45, 0.85], [0.05, 0.1, 0.35]]
stops = [0, 0.4, 1]
)toml");
        const double height = 0.5;  // sin(30 degrees) up; looking down, -0.5 wraps to the same 0.5
        const glm::dvec3 expected = glm::mix(glm::dvec3(0.25, 0.45, 0.85), glm::dvec3(0.05, 0.1, 0.35), (height - 0.4) / 0.6);
        for (test::Backend backend : {test::Backend::Cpu, test::Backend::Gpu}) {
            const FloatImage image = test::render_on(backend, scene);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(image.at(4, 4)[c], expected[c], 2e-3) << test::backend_name(backend) << " looking at " << look;
        }
    }
}

TEST(Sky, TheGpuDrawsTheReferencesPicture) {
    Scene scene = test::shipped_scene("seed", 160, 90, 2);
    scene.sky = Sky{{{0.0, {0.9, 0.95, 1.0}}, {0.4, {0.25, 0.45, 0.85}}, {1.0, {0.05, 0.1, 0.35}}}};
    test::expect_same_picture("sky_seed", to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                              to_srgb8(test::render_on(test::Backend::Cpu, scene)));
}

// POV-Ray's sky_sphere { pigment { bozo ... } }: the pattern's colour at the ray's unit direction,
// the sky's ramp its colours; looked at through a narrow camera in two directions.
TEST(Sky, APatternIsSeenAtTheRaysDirection) {
    for (const glm::dvec3 look : {glm::dvec3(0.3, 0.5, 1.0), glm::dvec3(-0.7, -0.2, 0.4)}) {
        const Scene scene = test::scene_from_text(fmt::format(R"toml(
[render]
width = 9
height = 9
samples = 1
[camera]
eye = [0, 0, 0]
fov = 0.1
look_at = [{}, {}, {}]
[sky]
colors = [[0, 0, 0.2], [1, 0.9, 0.8]]
pattern = {{ type = "turbulence", scale = 0.4, rotate = [0, 30, 0] }}
)toml", look.x, look.y, look.z));
        ASSERT_TRUE(scene.sky && scene.sky->pattern);
        const Pattern& p = *scene.sky->pattern;
        const glm::dvec3 q = glm::dvec3(glm::inverse(p.to_world) * glm::dvec4(glm::normalize(look), 1.0));
        const double f = cpu::pattern_value(p, q).value;
        const glm::dvec3 expected = glm::mix(glm::dvec3(0, 0, 0.2), glm::dvec3(1, 0.9, 0.8), f);
        for (test::Backend backend : {test::Backend::Cpu, test::Backend::Gpu}) {
            const FloatImage image = test::render_on(backend, scene);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(image.at(4, 4)[c], expected[c], 2e-3) << test::backend_name(backend);
        }
    }
}

TEST(Sky, TheGpuDrawsTheReferencesPatternedSky) {
    Scene scene = test::shipped_scene("seed", 160, 90, 2);
    Pattern clouds;
    clouds.type = PatternType::Turbulence;
    clouds.to_world = glm::dmat4(0.3);
    clouds.to_world[3][3] = 1.0;
    clouds.colors = {{0.0, {0.25, 0.45, 0.85}}, {1.0, {1.0, 1.0, 1.0}}};
    scene.sky = Sky{clouds.colors, clouds};
    test::expect_same_picture("sky_clouds_seed", to_srgb8(test::render_on(test::Backend::Gpu, scene)),
                              to_srgb8(test::render_on(test::Backend::Cpu, scene)));
}

TEST(Sky, ItsKeysAreChecked) {
    const std::string camera = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n";
    test::expect_scene_error(camera + "[sky]\ncolors = [[1, 1, 1]]\n", 5, 10, "a pattern needs 2 to 8 colors, not 1");
    test::expect_scene_error(camera + "[sky]\ncolors = [[1, 1, 1], [0, 0, 1]]\nstops = [0.5, 0.2]\n", 6, 15, "stops must not decrease");
    test::expect_scene_error(camera + "[sky]\ncolors = [[1, 1, 1], [0, 0, 1]]\npattern = { type = \"bozo\" }\n", 6, 20, "bozo");
    test::expect_scene_error(camera + "[sky]\ncolors = [[1, 1, 1], [0, 0, 1]]\npattern = { type = \"noise\", colors = [] }\n", 6, 29,
                             "unknown key 'colors'");
}

}  // namespace
}  // namespace lancer

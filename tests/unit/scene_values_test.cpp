// Numbers by name and by rule (scene/scene_values.hpp; docs/scene-format.md, "Numbers, names and
// loops"): [define] in the file's order, expressions of clock and frame, named vectors and
// POV-Ray's colours, repeat; and their errors, at the exact place.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "app/render_options.hpp"
#include "scene/animation.hpp"
#include "scene/load_scene.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

const char* const kCamera = "[camera]\neye = [0, 0, -5]\nlook_at = [0, 0, 0]\n";  // 3 lines

TEST(SceneValues, DefinesAreReadInOrderAndUsedByAnyNumber) {
    const Scene scene = test::scene_from_text(std::string(kCamera) + R"s(
        [define]
        r = 0.5
        d = "2*r"
        up = [0, "d", 0]
        [material.m]
        color = "SkyBlue"
        diffuse = "d - 0.25"
        [[object]]
        type = "sphere"
        center = "up"
        radius = "r*sqrt(4)"
        material = "m"
    )s");
    const auto& s = std::get<Sphere>(scene.objects.at(0).shape);
    EXPECT_EQ(s.radius, 1.0);
    EXPECT_EQ(s.center, dvec3(0.0, 1.0, 0.0));
    EXPECT_EQ(scene.materials.at(0).diffuse, 0.75);
    EXPECT_EQ(scene.materials.at(0).color, dvec3(0.196078, 0.6, 0.8));  // colors.inc's SkyBlue
    EXPECT_FALSE(scene.depends_on_time);
}

TEST(SceneValues, ClockAndFrameAreTheMomentTheSceneIsReadAt) {
    const std::string text = std::string(kCamera) + R"s(
        [define]
        angle = "360*clock"
        [[light]]
        position = ["10*cos(angle*pi/180)", 5, "frame"]
        [[object]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
    )s";
    const Scene still = test::scene_from_text(text);
    EXPECT_TRUE(still.depends_on_time);
    EXPECT_EQ(still.lights.at(0).position, dvec3(10.0, 5.0, 0.0));  // clock 0, frame 0
    const Scene later = parse_scene(text, "clock.toml", SceneTime{0.25, 7});
    EXPECT_NEAR(later.lights.at(0).position.x, 0.0, 1e-12);
    EXPECT_EQ(later.lights.at(0).position.z, 7.0);
}

TEST(SceneValues, AnAnimationReadsTheFileAgainForEachFrame) {
    const std::string path = test::output_dir() + "/clock_animation.toml";
    test::write_file(path, std::string(kCamera) + R"s(
        [material.m]
        specular = "0.2 + 0.6*clock"
        [[object]]
        type = "sphere"
        name = "ball"
        center = [0, 0, 0]
        radius = "1 + frame"
        material = "m"
        [animation]
        frames = 3
        [[animation.object]]
        object = "ball"
        keys = [{ time = 0.0, translate = [0, 0, 0] }, { time = 1.0, translate = [1, 0, 0] }]
    )s");
    RenderOptions options;
    options.scene = path;
    const Scene loaded = load_scene_with_overrides(options);
    const Scene last = scene_for_frame(options, loaded, 2);
    EXPECT_NEAR(last.materials.at(0).specular, 0.8, 1e-12);
    const auto& ball = std::get<Sphere>(last.objects.at(0).shape);
    EXPECT_EQ(ball.radius, 3.0);
    EXPECT_NEAR(ball.center.x, 1.0, 1e-12);  // and the tracks still move it
}

TEST(SceneValues, RepeatPlacesAnObjectForEachIndex) {
    const Scene scene = test::scene_from_text(std::string(kCamera) + R"s(
        [define]
        n = 5
        [[object]]
        type = "group"
        repeat = { j = [0, 1] }
        objects = [{ type = "sphere", repeat = { i = [1, "n"] }, center = ["i", "j", 0], radius = "0.1*i" }]
    )s");
    ASSERT_EQ(scene.objects.size(), 10u);
    const auto& s = std::get<Sphere>(scene.objects.at(7).shape);  // j = 1, i = 3
    EXPECT_EQ(s.center, dvec3(3.0, 1.0, 0.0));
    EXPECT_NEAR(s.radius, 0.3, 1e-15);
}

// POV-Ray's texture { } on an object in a #while loop: each copy its own material, its colour
// from the index.
TEST(SceneValues, AnObjectsOwnMaterialFollowsItsRepeat) {
    const Scene scene = test::scene_from_text(std::string(kCamera) + R"s(
        [[object]]
        type = "sphere"
        repeat = { i = [0, 2] }
        center = ["i", 0, 0]
        radius = 0.4
        material = { color = ["i/2", 0, "1 - i/2"], specular = 0 }
    )s");
    ASSERT_EQ(scene.objects.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        const Material& m = scene.materials.at(scene.objects[i].material);
        EXPECT_EQ(m.color, dvec3(i / 2.0, 0.0, 1.0 - i / 2.0));
        EXPECT_EQ(m.specular, 0.0);
    }
    test::expect_scene_error(std::string(kCamera) + "[[object]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = { colour = [1, 0, 0] }\n", 8, 14,
                             "did you mean 'color'");
}

// POV-Ray's #declare inside a #while: an object's own `define`, read again for each copy, seen by
// its members too, and gone after it.
TEST(SceneValues, AnObjectsOwnDefinesAreReadForEachCopy) {
    const Scene scene = test::scene_from_text(std::string(kCamera) + R"s(
        [[object]]
        type = "group"
        repeat = { j = [1, 2] }
        define = { y = "10 * j" }
        objects = [{ type = "sphere", repeat = { i = [0, 1] }, define = { x = "i + y" }, center = ["x", "y", 0], radius = 1 }]
        [[object]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
        define = { y = 5 }
    )s");
    ASSERT_EQ(scene.objects.size(), 5u);
    EXPECT_EQ(std::get<Sphere>(scene.objects[3].shape).center, dvec3(21.0, 20.0, 0.0));  // j = 2, i = 1
    test::expect_scene_error(std::string(kCamera) + "[define]\ny = 1\n[[object]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\n"
                                                    "define = { y = 2 }\n",
                             10, 16, "already a name");
}

// bench/port_check.sh's ports of POV-Ray's examples use these words on real scenes: they load,
// with the objects their originals make.
TEST(SceneValues, ThePortsOfPovRaysExamplesLoad) {
    int ports = 0;
    for (const auto& e : std::filesystem::directory_iterator(test::source_path("bench/port")))
        if (e.path().extension() == ".toml") {
            EXPECT_FALSE(load_scene(e.path().string()).objects.empty()) << e.path();
            ++ports;
        }
    EXPECT_GE(ports, 6);
    EXPECT_EQ(load_scene(test::source_path("bench/port/perspective.toml")).objects.size(), 16u);  // floor, 14 boxes, sphere
    const Scene sombrero = load_scene(test::source_path("bench/port/sombrero.toml"));
    EXPECT_EQ(sombrero.objects.size(), 33u * 33u);
    EXPECT_EQ(sombrero.materials.size(), 33u * 33u + 1u);  // each sphere's own, and the default
}

TEST(SceneValues, ErrorsSayWhereAndWhy) {
    const std::string sphere = "[[object]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\n";  // lines 4-6
    test::expect_scene_error(std::string(kCamera) + sphere + "radius = \"1 + big\"\n", 7, 15, "big");
    test::expect_scene_error(std::string(kCamera) + "[define]\na = \"b\"\nb = 1\n" + sphere + "radius = 1\n", 5, 6, "b");
    test::expect_scene_error(std::string(kCamera) + "[define]\nsin = 1\n" + sphere + "radius = 1\n", 5, 7, "already a name");
    test::expect_scene_error(std::string(kCamera) + "[define]\nclock = 1\n", 5, 9, "already a name");
    test::expect_scene_error(std::string(kCamera) + "[material.m]\ncolor = \"Redd\"\n", 5, 9, "did you mean 'Red'");
    test::expect_scene_error(std::string(kCamera) + "[material.m]\ncolor = \"Clear\"\n", 5, 9, "neither a vector");
    test::expect_scene_error(std::string(kCamera) + sphere + "radius = \"log(0)\"\n", 7, 10, "not a finite number");
    test::expect_scene_error(std::string(kCamera) + sphere + "radius = 1\nrepeat = { i = [0, 2.5] }\n", 8, 16, "whole numbers");
    test::expect_scene_error(std::string(kCamera) + sphere + "radius = 1\nrepeat = { i = [0, 1], j = [0, 1] }\n", 8, 10,
                             "one index");
    test::expect_scene_error(std::string(kCamera) + sphere + "radius = 1\nrepeat = { i = [0, 10000000] }\n", 8, 16,
                             "beyond the 65536 copies and placements");
    test::expect_scene_error(std::string(kCamera) + "[define]\ni = 1\n" + sphere + "radius = 1\nrepeat = { i = [0, 1] }\n", 10,
                             16, "already a name");
}

}  // namespace
}  // namespace lancer

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "scene/load_scene.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

TEST(SceneLoader, ReadsEveryTableOfAGoodScene) {
    Scene s = test::scene_from_text(R"(
        [render]
        width = 320
        height = 200
        samples = 2
        max_depth = 3
        background = [0.1, 0.2, 0.3]
        [camera]
        eye = [0, 3, -9]
        look_at = [0, 0.8, 0]
        fov = 50
        [ambient]
        color = [0.5, 0.5, 0.5]
        [[light]]
        position = [-6, 10, -6]
        color = [0.8, 0.8, 0.8]
        [material.red]
        color = [0.9, 0.1, 0.1]
        specular = 0.5
        shininess = 30
        reflection = 0.3
        [material.floor]
        checker = { colors = [[1, 1, 1], [0.5, 0.5, 0.5]], size = 2 }
        [[object]]
        type = "sphere"
        center = [0, 1, 0]
        radius = 1
        material = "red"
        [[object]]
        type = "box"
        min = [-1, 0, -1]
        max = [1, 2, 1]
    )");
    EXPECT_EQ(s.render.width, 320);
    EXPECT_EQ(s.render.height, 200);
    EXPECT_EQ(s.render.samples, 2);
    EXPECT_EQ(s.render.max_depth, 3);
    EXPECT_EQ(s.render.background, dvec3(0.1, 0.2, 0.3));
    EXPECT_EQ(s.camera.eye, dvec3(0, 3, -9));
    EXPECT_EQ(s.camera.up, dvec3(0, 1, 0));  // default
    EXPECT_EQ(s.camera.fov_deg, 50.0);
    EXPECT_EQ(s.ambient, dvec3(0.5));
    ASSERT_EQ(s.lights.size(), 1u);
    ASSERT_EQ(s.materials.size(), 3u);  // red, floor and the implicit default
    const Material& red = s.materials[s.objects[0].material];
    EXPECT_EQ(red.name, "red");
    EXPECT_EQ(red.specular, 0.5);
    EXPECT_EQ(red.diffuse, 0.6);  // POV-Ray's default
    EXPECT_EQ(red.ambient, 0.1);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.materials[s.objects[1].material].name, "default");
    const auto& floor = s.materials[0];  // [material.*] tables are read in key order
    ASSERT_TRUE(floor.checker);
    EXPECT_EQ(floor.checker->size, 2.0);
    EXPECT_EQ(s.objects[1].where.line, 29);
}

TEST(SceneLoader, NormalisesPlaneNormals) {
    Scene s = test::scene_from_text(R"(
        [camera]
        eye = [0, 0, -5]
        look_at = [0, 0, 0]
        [[object]]
        type = "plane"
        normal = [0, 3, 0]
    )");
    EXPECT_EQ(std::get<Plane>(s.objects[0].shape).normal, dvec3(0, 1, 0));
}

TEST(SceneLoader, EveryShippedSceneLoads) {
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenes"))) {
        if (entry.path().extension() != ".toml") continue;
        EXPECT_NO_THROW(load_scene(entry.path().string())) << entry.path();
        ++count;
    }
    EXPECT_GE(count, 3);
}

TEST(SceneLoader, ReadsAnImplicitSurface) {
    Scene s = test::scene_from_text(R"toml(
        [camera]
        eye = [0, 0, -5]
        look_at = [0, 0, 0]
        [[object]]
        type = "implicit"
        function = "(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + z^2)"
        params = { R = 1, r = 0.35 }
        box = { min = [-1.4, -0.4, -1.4], max = [1.4, 0.4, 1.4] }
        transform = { scale = 2, translate = [0, 1, 0] }
        [[object]]
        type = "implicit"
        function = "sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)"
        box = { min = [-3, -3, -3], max = [3, 3, 3] }
    )toml");
    ASSERT_EQ(s.objects.size(), 2u);
    const auto& torus = *std::get<ImplicitObject>(s.objects[0].shape).surface;
    EXPECT_EQ(torus.degree(), 4);
    EXPECT_EQ(torus.box_lo, glm::dvec3(-1.4, -0.4, -1.4));
    EXPECT_EQ(torus.box_hi, glm::dvec3(1.4, 0.4, 1.4));
    EXPECT_EQ(glm::dvec3(torus.to_world * glm::dvec4(1, 0, 0, 1)), glm::dvec3(2, 1, 0));
    EXPECT_EQ(glm::dvec3(torus.to_local * glm::dvec4(2, 1, 0, 1)), glm::dvec3(1, 0, 0));
    const auto& gyroid = *std::get<ImplicitObject>(s.objects[1].shape).surface;
    EXPECT_FALSE(gyroid.polynomial);
    EXPECT_EQ(gyroid.degree(), 0);
}

TEST(SceneLoader, UnreadableFileIsAUserError) {
    EXPECT_THROW(load_scene("/nonexistent/scene.toml"), UserError);
    EXPECT_THROW(load_scene(test::source_path("scenes")), UserError);  // a directory
}

// Each file in tests/data/bad/ starts with "# expect: LINE:COL: error: MESSAGE"; loading it must
// fail with exactly that location and a message starting with MESSAGE.
class BadScene : public testing::TestWithParam<std::string> {};

TEST_P(BadScene, FailsWithTheExpectedLocationAndMessage) {
    std::string path = GetParam();
    std::ifstream in(path);
    std::string first;
    std::getline(in, first);
    const std::string tag = "# expect: ";
    ASSERT_EQ(first.rfind(tag, 0), 0u) << path << " lacks an expect line";
    std::string expected = path + ":" + first.substr(tag.size());
    try {
        load_scene(path);
        FAIL() << path << " loaded without error";
    } catch (const SceneError& e) {
        std::string got = format_error(e);
        EXPECT_EQ(got.substr(0, expected.size()), expected);
    }
}

std::vector<std::string> bad_scenes() {
    std::vector<std::string> paths;
    for (const auto& e : std::filesystem::directory_iterator(test::source_path("tests/data/bad")))
        if (e.path().extension() == ".toml") paths.push_back(e.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

INSTANTIATE_TEST_SUITE_P(Data, BadScene, testing::ValuesIn(bad_scenes()), [](const auto& info) {
    return std::filesystem::path(info.param).stem().string();
});

}  // namespace
}  // namespace lancer

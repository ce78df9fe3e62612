// `lancer watch` end to end: a watcher on a temporary copy of shaders/ and a scene, changed the
// way an editor changes them, observed through its output file and its log with bounded waits.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

#include <sys/stat.h>

#include <gtest/gtest.h>

#include "image/image.hpp"
#include "support/child_process.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

const char* kScene = R"(
[render]
width = 32
height = 18
samples = 1
background = [0.2, 0.3, 0.5]
[camera]
eye = [0, 0, -6]
look_at = [0, 0, 0]
[[light]]
position = [-5, 5, -5]
[material.red]
color = [0.9, 0.1, 0.1]
[[object]]
type = "sphere"
center = [SPHERE_X, 0, 0]
radius = 1
material = "red"
)";

std::string scene_text(const std::string& sphere_x) {
    std::string s = kScene;
    s.replace(s.find("SPHERE_X"), 8, sphere_x);
    return s;
}

ino_t inode(const fs::path& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 ? st.st_ino : 0;
}

class Watch : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::path(test::output_dir()) / ("watch-" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        fs::copy(test::source_path("shaders"), dir / "shaders", fs::copy_options::recursive);
        test::write_file(dir / "scene.toml", scene_text("0"));
        child = std::make_unique<test::ChildProcess>(
            std::vector<std::string>{"watch", "scene.toml", "-o", "out.png", "--shaders", "shaders"}, dir.string(),
            (dir / "log.txt").string());
        ASSERT_TRUE(test::ChildProcess::wait_until([&] { return child->log().find("watch: ") != std::string::npos; }))
            << child->log();
    }
    void TearDown() override {
        if (child->running()) {
            child->interrupt();
            EXPECT_EQ(child->wait_exit(), 0) << child->log();
        }
        EXPECT_EQ(child->log().find("validation"), std::string::npos) << child->log();
    }
    bool wait_for_count(const std::string& what, int n) {
        return test::ChildProcess::wait_until([&] { return test::count_occurrences(child->log(), what) >= n; });
    }
    Rgb8Image output() { return read_png((dir / "out.png").string()); }

    fs::path dir;
    std::unique_ptr<test::ChildProcess> child;
};

TEST_F(Watch, ShaderEditsRecompileAndErrorsKeepTheLastGoodImage) {
    // A changed background colour in the shader source reaches the PNG.
    fs::path trace = dir / "shaders/trace.comp";
    std::string source = test::read_file(trace);
    const std::string miss = "color += weight * frame.background.rgb;";
    ASSERT_NE(source.find(miss), std::string::npos) << "the test edits this line of trace.comp";
    std::string magenta = source;
    magenta.replace(magenta.find(miss), miss.size(), "color += weight * vec3(1.0, 0.0, 1.0);");
    test::write_file(trace, magenta);
    ASSERT_TRUE(wait_for_count("reload: ", 1)) << child->log();
    Rgb8Image img = output();
    EXPECT_EQ(img.at(0, 0)[0], 255);
    EXPECT_EQ(img.at(0, 0)[1], 0);
    EXPECT_EQ(img.at(0, 0)[2], 255);

    // A syntax error in an included file names that file and line; image and process survive.
    fs::path shade = dir / "shaders/shade.glsl";
    std::string good_shade = test::read_file(shade);
    int lines = static_cast<int>(std::count(good_shade.begin(), good_shade.end(), '\n'));
    test::write_file(shade, good_shade + "this is not glsl(\n");
    ASSERT_TRUE(wait_for_count("compile failed", 1)) << child->log();
    std::string expected_location = "shaders/shade.glsl:" + std::to_string(lines + 1) + ": error:";
    EXPECT_NE(child->log().find(expected_location), std::string::npos) << child->log();
    EXPECT_EQ(output().bytes, img.bytes);
    EXPECT_TRUE(child->running());

    // Fixing it renders again: a new file replaces the old one.
    ino_t before = inode(dir / "out.png");
    test::write_file(shade, good_shade);
    ASSERT_TRUE(wait_for_count("reload: ", 3)) << child->log();
    EXPECT_NE(inode(dir / "out.png"), before);
    EXPECT_EQ(output().at(0, 0)[1], 0);  // still magenta
}

TEST_F(Watch, SceneEditsRerenderAndBrokenScenesKeepTheLastGoodImage) {
    Rgb8Image centred = output();
    test::write_file(dir / "scene.toml", scene_text("1.5"));
    ASSERT_TRUE(wait_for_count("reload: ", 1)) << child->log();
    Rgb8Image moved = output();
    EXPECT_NE(moved.bytes, centred.bytes);

    test::write_file(dir / "scene.toml", scene_text("1.5") + "\n[[object]]\ntype = \"sphere\"\nradius = -1\ncenter = [0, 0, 0]\n");
    ASSERT_TRUE(wait_for_count("scene error", 1)) << child->log();
    EXPECT_TRUE(std::regex_search(child->log(), std::regex(R"(scene\.toml:\d+:\d+: error: sphere radius must be positive)")))
        << child->log();
    EXPECT_EQ(output().bytes, moved.bytes);
    EXPECT_TRUE(child->running());
}

TEST_F(Watch, ABurstOfWritesIsOneReload) {
    fs::path common = dir / "shaders/common.glsl";
    std::string text = test::read_file(common);
    for (int i = 0; i < 5; ++i) test::write_file(common, text + "// save " + std::to_string(i) + "\n");
    ASSERT_TRUE(wait_for_count("common.glsl changed", 1)) << child->log();
    // A later scene edit is a sentinel: a second reload for the burst would come before it.
    test::write_file(dir / "scene.toml", scene_text("0.5"));
    ASSERT_TRUE(wait_for_count("scene.toml changed", 1)) << child->log();
    EXPECT_EQ(test::count_occurrences(child->log(), "common.glsl changed"), 1) << child->log();
}

TEST_F(Watch, InterruptExitsCleanly) {
    child->interrupt();
    EXPECT_EQ(child->wait_exit(), 0) << child->log();
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// --frame previews one moment of an animation: the same image `lancer render --frames N` makes.
TEST(WatchFrame, PreviewsTheRequestedFrameOfAnAnimation) {
    fs::path dir = fs::path(test::output_dir()) / ("watch-frame-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    test::write_file(dir / "anim.toml", scene_text("0.5") + R"(
[animation]
frames = 8
[animation.camera_orbit]
center = [0, 0, 0]
radius = 6
height = 1
)");
    test::ChildProcess child({"watch", "anim.toml", "-o", "watched.png", "--frame", "3"}, dir.string(),
                             (dir / "log.txt").string());
    ASSERT_TRUE(test::ChildProcess::wait_until([&] { return child.log().find("watch: ") != std::string::npos; }))
        << child.log();
    child.interrupt();
    EXPECT_EQ(child.wait_exit(), 0) << child.log();
    auto r = test::run_lancer("render " + (dir / "anim.toml").string() + " --frames 3 -q -o " + (dir / "rendered.png").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_png((dir / "watched.png").string()).bytes, read_png((dir / "rendered.png").string()).bytes);
    auto frame0 = test::run_lancer("render " + (dir / "anim.toml").string() + " --frames 0 -q -o " + (dir / "f0.png").string());
    ASSERT_EQ(frame0.exit_code, 0) << frame0.err;
    EXPECT_NE(read_png((dir / "watched.png").string()).bytes, read_png((dir / "f0.png").string()).bytes);
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// A texture is part of its scene: rewriting the image re-renders, and an image that no longer
// reads is a scene error that keeps the last good picture.
TEST_F(Watch, TextureEditsRerenderTheScene) {
    auto write_texture = [&](std::uint8_t r, std::uint8_t g, std::uint8_t b) {
        write_png((dir / "tex.png").string(), Rgb8Image{1, 1, {r, g, b}});
    };
    write_texture(255, 0, 0);
    std::string textured = scene_text("0");
    const std::string color = "color = [0.9, 0.1, 0.1]";
    textured.replace(textured.find(color), color.size(), "texture = \"tex.png\"");
    test::write_file(dir / "scene.toml", textured);
    ASSERT_TRUE(wait_for_count("reload: ", 1)) << child->log();
    const std::uint8_t* centre = output().at(16, 9);
    EXPECT_GT(centre[0], centre[2]);  // red

    write_texture(0, 0, 255);
    ASSERT_TRUE(wait_for_count("reload: tex.png changed", 1)) << child->log();
    Rgb8Image blue = output();
    EXPECT_GT(blue.at(16, 9)[2], blue.at(16, 9)[0]);

    test::write_file(dir / "tex.png", "not a picture any more");
    ASSERT_TRUE(wait_for_count("scene error", 1)) << child->log();
    EXPECT_NE(child->log().find("scene.toml:13:11: error: cannot read texture 'tex.png': not a PNG, JPEG or BMP image"),
              std::string::npos)
        << child->log();
    EXPECT_EQ(output().bytes, blue.bytes);
    EXPECT_TRUE(child->running());
}

}  // namespace
}  // namespace lancer

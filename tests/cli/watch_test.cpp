// `lancer watch` end to end: a watcher on a temporary copy of shaders/ and a scene, changed the
// way an editor changes them, observed through its output file and its log with bounded waits.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <sys/stat.h>

#include <gtest/gtest.h>

#include "image/image.hpp"
#include "support/child_process.hpp"
#include "support/test_support.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;

const char* kWatchedScene = R"(
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

// The end of the line `lancer watch` prints once the first image is written (or the scene failed).
const char* const kStarted = "; watching ";

std::string scene_text(const std::string& sphere_x) {
    std::string s = kWatchedScene;
    s.replace(s.find("SPHERE_X"), 8, sphere_x);
    return s;
}

ino_t inode(const fs::path& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 ? st.st_ino : 0;
}

// One flat bicubic patch in the plane z = 0, a `size` square from (x, y): a .bpt file.
std::string square_patch(double x, double y, double size) {
    std::string s = "1\n3 3\n";
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) s += std::to_string(x + size * i / 3.0) + " " + std::to_string(y + size * j / 3.0) + " 0\n";
    return s;
}

std::string patch_scene(const std::string& patch_file) {
    return scene_text("-20") + "[[object]]\ntype = \"bezier\"\nfile = \"" + patch_file + "\"\nmaterial = \"red\"\n";
}

// A watcher in a directory of its own, started by each test as it needs.
class WatchTest : public testing::Test {
protected:
    void SetUp() override {
        std::string name = testing::UnitTest::GetInstance()->current_test_info()->name();
        dir = fs::path(test::output_dir()) / ("watch-" + name + "-" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override {
        if (!child) return;
        if (child->running()) {
            child->interrupt();
            EXPECT_EQ(child->wait_exit(), 0) << child->log();
        }
        EXPECT_EQ(child->log().find("validation"), std::string::npos) << child->log();
    }
    // Runs `lancer watch ARGS -o out.png` in the directory and waits until it has started.
    void start(std::vector<std::string> args) {
        args.insert(args.begin(), "watch");
        args.insert(args.end(), {"-o", "out.png"});
        child = std::make_unique<test::ChildProcess>(args, dir.string(), (dir / "log.txt").string());
        ASSERT_TRUE(test::ChildProcess::wait_until([&] { return child->log().find(kStarted) != std::string::npos; }))
            << child->log();
    }
    void copy_shaders() { fs::copy(test::source_path("shaders"), dir / "shaders", fs::copy_options::recursive); }
    // Edits the copy's trace.comp: rays that miss everything see magenta, not the background.
    void paint_the_background_magenta() {
        fs::path trace = dir / "shaders/trace.comp";
        std::string source = test::read_file(trace);
        const std::string miss = "color += b.weight * frame.background.rgb;";
        ASSERT_NE(source.find(miss), std::string::npos) << "the test edits this line of trace.comp";
        source.replace(source.find(miss), miss.size(), "color += b.weight * vec3(1.0, 0.0, 1.0);");
        test::write_file(trace, source);
    }
    static void expect_magenta_corner(const Rgb8Image& img) {
        EXPECT_EQ(img.at(0, 0)[0], 255);
        EXPECT_EQ(img.at(0, 0)[1], 0);
        EXPECT_EQ(img.at(0, 0)[2], 255);
    }
    bool wait_for_count(const std::string& what, int n) {
        return test::ChildProcess::wait_until([&] { return test::count_occurrences(child->log(), what) >= n; });
    }
    bool wait_for_output_unlike(const Rgb8Image& image) {
        return test::ChildProcess::wait_until([&] { return output().bytes != image.bytes; });
    }
    Rgb8Image output() { return read_png((dir / "out.png").string()); }
    // `lancer render` of a scene of the directory (the built-in shaders).
    Rgb8Image render(const std::string& scene) {
        auto r = test::run_lancer("render " + (dir / scene).string() + " -q -o " + (dir / "rendered.png").string());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return read_png((dir / "rendered.png").string());
    }
    // The reload lines that name `file` among the changed files.
    int reloads_naming(const std::string& file) {
        std::istringstream lines(child->log());
        int n = 0;
        for (std::string line; std::getline(lines, line);)
            if (line.rfind("reload: ", 0) == 0 && line.substr(0, line.find(" changed")).find(file) != std::string::npos) ++n;
        return n;
    }

    fs::path dir;
    std::unique_ptr<test::ChildProcess> child;
};

// The issue's set-up: a copy of shaders/ and a scene with a sphere.
class Watch : public WatchTest {
protected:
    void SetUp() override {
        WatchTest::SetUp();
        copy_shaders();
        test::write_file(dir / "scene.toml", scene_text("0"));
        start({"scene.toml", "--shaders", "shaders"});
    }
};

TEST_F(Watch, ShaderEditsRecompileAndErrorsKeepTheLastGoodImage) {
    // A changed background colour in the shader source reaches the PNG.
    ASSERT_NO_FATAL_FAILURE(paint_the_background_magenta());
    ASSERT_TRUE(wait_for_count("reload: ", 1)) << child->log();
    Rgb8Image img = output();
    expect_magenta_corner(img);

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

// A burst that breaks a shader and edits the scene: the scene is reloaded all the same, drawn
// with the last good shaders; fixing the shader then draws the new scene, not the old one.
TEST_F(Watch, ABrokenShaderInTheSameBurstAsASceneEditStillAppliesTheScene) {
    Rgb8Image centred = output();
    fs::path shade = dir / "shaders/shade.glsl";
    std::string good_shade = test::read_file(shade);
    test::write_file(shade, good_shade + "this is not glsl(\n");
    test::write_file(dir / "scene.toml", scene_text("1.5"));
    ASSERT_TRUE(wait_for_count("compile failed", 1)) << child->log();
    ASSERT_TRUE(wait_for_output_unlike(centred)) << child->log();
    EXPECT_EQ(output().bytes, render("scene.toml").bytes);

    test::write_file(shade, good_shade);
    ASSERT_TRUE(wait_for_count("changed: compiled in", 1)) << child->log();
    EXPECT_EQ(output().bytes, render("scene.toml").bytes) << child->log();
    EXPECT_TRUE(child->running());
}

// A file the scene references is part of the scene: editing it reloads the scene. Once the scene
// no longer references it, its edits are ignored.
TEST_F(WatchTest, ReferencedFilesAreWatchedForAsLongAsTheSceneReferencesThem) {
    test::write_file(dir / "a.bpt", square_patch(-2, -1, 1.5));
    test::write_file(dir / "b.bpt", square_patch(0.5, -1, 1.5));
    test::write_file(dir / "scene.toml", patch_scene("a.bpt"));
    start({"scene.toml"});
    EXPECT_NE(child->log().find("and the 1 file(s) it references"), std::string::npos) << child->log();
    Rgb8Image first = output();

    test::write_file(dir / "a.bpt", square_patch(-1, 0, 1.5));
    ASSERT_TRUE(wait_for_count("reload: a.bpt changed", 1)) << child->log();
    EXPECT_NE(output().bytes, first.bytes);
    EXPECT_EQ(output().bytes, render("scene.toml").bytes);

    test::write_file(dir / "scene.toml", patch_scene("b.bpt"));
    ASSERT_TRUE(wait_for_count("reload: scene.toml changed", 1)) << child->log();
    test::write_file(dir / "a.bpt", square_patch(-2, -1, 1.5));
    // b's edit is a sentinel: a reload for the earlier edit of a would come before it.
    test::write_file(dir / "b.bpt", square_patch(0, 0, 1));
    ASSERT_TRUE(wait_for_count("b.bpt", 1)) << child->log();
    EXPECT_EQ(reloads_naming("a.bpt"), 1) << child->log();
    EXPECT_EQ(output().bytes, render("scene.toml").bytes);
}

// The scene is edited to reference a patch file that is broken: the error is reported, and that
// file is watched from then on, so fixing it (not touching the scene again) shows the patch.
TEST_F(WatchTest, ABrokenFileTheSceneBeginsToReferenceIsWatchedUntilFixed) {
    test::write_file(dir / "a.bpt", square_patch(-2, -1, 1.5));
    test::write_file(dir / "b.bpt", "1\n3 3\n0 0 0\n");  // 1 of 16 points
    test::write_file(dir / "scene.toml", patch_scene("a.bpt"));
    start({"scene.toml"});
    test::write_file(dir / "scene.toml", patch_scene("b.bpt"));
    ASSERT_TRUE(wait_for_count("reload: scene.toml changed: scene error", 1)) << child->log();
    EXPECT_NE(child->log().find("b.bpt:"), std::string::npos) << child->log();

    test::write_file(dir / "b.bpt", square_patch(0.5, -1, 1.5));
    ASSERT_TRUE(wait_for_count("reload: b.bpt changed: scene reloaded", 1)) << child->log();
    EXPECT_EQ(output().bytes, render("scene.toml").bytes);
}

// A scene is whatever file the scene argument names (`render` accepts any name), not a .toml.
TEST_F(WatchTest, ASceneFileNotNamedTomlReloadsOnEdit) {
    test::write_file(dir / "sphere.scene", scene_text("0"));
    start({"sphere.scene"});
    Rgb8Image centred = output();
    test::write_file(dir / "sphere.scene", scene_text("1.5"));
    ASSERT_TRUE(wait_for_count("reload: sphere.scene changed", 1)) << child->log();
    EXPECT_EQ(child->log().find("compile"), std::string::npos) << child->log();
    EXPECT_NE(output().bytes, centred.bytes);
    EXPECT_EQ(output().bytes, render("sphere.scene").bytes);
}

// Shader sources broken from the start: the compiler's messages, a clear word that the built-in
// shaders draw until they compile, and the watch goes on.
TEST_F(WatchTest, ABrokenFirstCompileIsReportedAndTheBuiltInShadersDraw) {
    copy_shaders();
    fs::path shade = dir / "shaders/shade.glsl";
    std::string good_shade = test::read_file(shade);
    int lines = static_cast<int>(std::count(good_shade.begin(), good_shade.end(), '\n'));
    test::write_file(shade, good_shade + "this is not glsl(\n");
    test::write_file(dir / "scene.toml", scene_text("0"));
    start({"scene.toml", "--shaders", "shaders"});
    std::string log = child->log();
    EXPECT_NE(log.find("shaders/shade.glsl:" + std::to_string(lines + 1) + ": error:"), std::string::npos) << log;
    EXPECT_NE(log.find("watch: shaders/ does not compile; using the built-in shaders until it does"), std::string::npos) << log;
    EXPECT_EQ(log.find("compiled in"), std::string::npos) << log;
    EXPECT_EQ(output().bytes, render("scene.toml").bytes);

    // Fixed, with a magenta background: the watched sources draw from now on.
    ASSERT_NO_FATAL_FAILURE(paint_the_background_magenta());
    test::write_file(shade, good_shade);
    ASSERT_TRUE(wait_for_count("changed: compiled in", 1)) << child->log();
    expect_magenta_corner(output());
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
    ASSERT_TRUE(test::ChildProcess::wait_until([&] { return child.log().find(kStarted) != std::string::npos; }))
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
    Rgb8Image red = output();
    EXPECT_GT(red.at(16, 9)[0], red.at(16, 9)[2]);

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

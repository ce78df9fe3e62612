// `lancer view` end to end: the viewer in a virtual X server (Xvfb), driven by xdotool like a
// user, observed through what it writes (--dump-frame: the window's pixels after each finished
// refinement; its log lines; the files p, f and l write) and through screenshots, with bounded
// waits, never fixed sleeps. Every run is under the Vulkan validation layer.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <regex>
#include <sstream>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "image/diff.hpp"
#include "scene/camera.hpp"
#include "support/child_process.hpp"
#include "support/test_support.hpp"
#include "support/x_server.hpp"
#include "view/camera_controller.hpp"
#include "view/camera_text.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;
using std::chrono::seconds;

// A small scene with what can go wrong in a moved picture: silhouettes, shadows, a mirror and a
// checkerboard. The camera comes first, as an inline table, so tests can put any camera there.
const char* kSceneBody = R"(
[render]
width = 96
height = 54
samples = 3
background = [0.42, 0.56, 0.78]
[[light]]
position = [-6, 10, -6]
color = [0.8, 0.8, 0.8]
[[light]]
position = [6, 8, -4]
color = [0.4, 0.4, 0.4]
[material.red]
color = [0.9, 0.1, 0.1]
specular = 0.5
shininess = 30
[material.mirror]
color = [0.9, 0.9, 0.9]
reflection = 0.7
[material.floor]
checker = { colors = [[1, 1, 1], [0.4, 0.4, 0.4]], size = 1.0 }
[[object]]
type = "sphere"
center = [-1.2, 1, 0]
radius = 1
material = "red"
[[object]]
type = "sphere"
center = [1.3, 1, 0.8]
radius = 1
material = "mirror"
[[object]]
type = "rectangle"
corner = [-8, 0, -8]
edge_u = [16, 0, 0]
edge_v = [0, 0, 16]
material = "floor"
)";

CameraSpec file_camera() {
    CameraSpec c;
    c.eye = {0.0, 3.0, -8.0};
    c.look_at = {0.0, 0.8, 0.0};
    c.up = {0.0, 1.0, 0.0};
    c.fov_deg = 45.0;
    return c;
}

std::string scene_text(const CameraSpec& camera) {
    return "camera = { " + view::camera_toml(camera) + " }\n" + kSceneBody;
}

dvec3 parse_vec(const std::string& text) {
    dvec3 v;
    std::sscanf(text.c_str(), "%lf, %lf, %lf", &v.x, &v.y, &v.z);
    return v;
}

// The camera of the last line starting with `prefix` ("view: refined", "view: saved").
std::optional<CameraSpec> last_camera(const std::string& log, const std::string& prefix) {
    static const std::regex camera(R"(camera: eye = \[([^\]]*)\], look_at = \[([^\]]*)\], up = \[([^\]]*)\], fov = (\S+))");
    std::optional<CameraSpec> found;
    std::istringstream lines(log);
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (line.rfind(prefix, 0) != 0 || !std::regex_search(line, m, camera)) continue;
        CameraSpec c;
        c.eye = parse_vec(m[1]);
        c.look_at = parse_vec(m[2]);
        c.up = parse_vec(m[3]);
        c.fov_deg = std::stod(m[4]);
        found = c;
    }
    return found;
}

bool near(const dvec3& a, const dvec3& b, double tolerance) { return glm::length(a - b) <= tolerance; }

class View : public testing::Test {
protected:
    void SetUp() override {
        try {
            x = std::make_unique<test::XServer>();
        } catch (const std::exception& e) {
            FAIL() << e.what();  // never skipped: setup.sh installs Xvfb
        }
        for (const char* tool : {"xdotool", "xwd"})
            if (!test::have_program(tool))
                FAIL() << tool << " is not installed: the viewer's tests need it (Debian packages xdotool, x11-apps; "
                       << "./setup.sh installs them)";
        ::setenv("DISPLAY", x->display().c_str(), 1);  // the viewer and the X tools inherit it
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::path(test::output_dir()) / (std::string("view-") + info->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        test::write_file(dir / "scene.toml", scene_text(file_camera()));
    }

    void TearDown() override {
        if (child && child->running()) {
            child->interrupt();
            expect_clean_exit();
        }
        if (child) {
            EXPECT_EQ(log().find("validation"), std::string::npos) << log();
        }
    }

    // Starts the viewer and waits for its first finished picture and its window.
    void start(std::vector<std::string> extra = {}, const std::string& scene = "scene.toml") {
        std::vector<std::string> args = {"view", scene, "--dump-frame", "dump.png"};
        args.insert(args.end(), extra.begin(), extra.end());
        child = std::make_unique<test::ChildProcess>(args, dir.string(), (dir / "log.txt").string());
        ASSERT_TRUE(wait_for_count("view: refined", 1)) << log();
        window = x->find_window("lancer");
        ASSERT_FALSE(window.empty()) << "no lancer window on " << x->display();
        // No window manager: keyboard focus follows the pointer, so the pointer goes in the window.
        ASSERT_EQ(xdotool("windowfocus --sync " + window + " mousemove --sync --window " + window + " 3 3"), 0);
    }

    void copy_shaders() { fs::copy(test::source_path("shaders"), dir / "shaders", fs::copy_options::recursive); }
    int xdotool(const std::string& args) { return x->run("timeout 30 xdotool " + args); }
    void keys(const std::string& names) { ASSERT_EQ(xdotool("key --delay 20 " + names), 0); }

    std::string log() const { return child ? child->log() : ""; }
    // Waits for the viewer to exit and expects status 0. In the sanitizer build one failure is
    // not the viewer's: LeakSanitizer's own leak check at exit crashes now and then while the
    // whole suite loads the machine ("Tracer caught signal 11", then "LeakSanitizer has
    // encountered a fatal error" and status 1; google/sanitizers#1353): once in a CI run on
    // 2026-12-01, never in 360 runs of these tests alone. That is reported and let through; a
    // leak it finds ("detected memory leaks"), or any other failure, still fails the test.
    void expect_clean_exit() {
        const int status = child->wait_exit();
        const std::string text = log();
        const bool leak_check_crashed = status == 1 && text.find("LeakSanitizer has encountered a fatal error") != std::string::npos &&
                                        text.find("Tracer caught signal") != std::string::npos &&
                                        text.find("detected memory leaks") == std::string::npos;
        if (leak_check_crashed) {
            std::cerr << "view test: LeakSanitizer's leak check crashed at the viewer's exit (not a leak; see expect_clean_exit)\n";
            return;
        }
        EXPECT_EQ(status, 0) << text;
    }
    bool wait_for_count(const std::string& what, int n, seconds timeout = seconds(60)) {
        return test::ChildProcess::wait_until([&] { return test::count_occurrences(log(), what) >= n; }, timeout);
    }
    // Waits until a finished refinement shows a camera whose eye is `eye`.
    bool wait_for_refined_eye(const dvec3& eye) {
        return test::ChildProcess::wait_until([&] {
            auto c = last_camera(log(), "view: refined");
            return c && near(c->eye, eye, 1e-9);
        });
    }

    Rgb8Image dump() const { return read_png((dir / "dump.png").string()); }

    // Presses h and waits on the window's pixels until the help is over `picture`; `screen`
    // is then the screenshot (also saved as help.png, to look at).
    void show_help(const Rgb8Image& picture, Rgb8Image& screen) {
        keys("h");
        ASSERT_TRUE(test::ChildProcess::wait_until([&] {
            screen = x->screenshot(window);
            return screen.bytes != picture.bytes;
        }, seconds(30)));
        write_png((dir / "help.png").string(), screen);
    }

    // `lancer render` of the test scene with `camera` (and `options`).
    Rgb8Image render(const CameraSpec& camera, const std::string& name = "reference", const std::string& options = "") {
        fs::path scene = dir / (name + ".toml"), png = dir / (name + ".png");
        test::write_file(scene, scene_text(camera));
        auto r = test::run_lancer("render " + scene.string() + options + " -q -o " + png.string());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return read_png(png.string());
    }

    void expect_like(const Rgb8Image& shown, const Rgb8Image& rendered, const std::string& name) {
        test::expect_same_picture("view-" + name, shown, rendered);
    }

    std::unique_ptr<test::XServer> x;
    fs::path dir;
    std::unique_ptr<test::ChildProcess> child;
    std::string window;
};

TEST_F(View, FirstPictureIsWhatLancerRenderMakesAndTheWindowShowsIt) {
    start();
    Rgb8Image shown = dump();
    Rgb8Image rendered = render(file_camera());
    expect_like(shown, rendered, "first");
    // Refinement adds the same samples in the same order as one render: the same bytes.
    EXPECT_EQ(shown.bytes, rendered.bytes) << test::save_comparison("view-first-exact", shown, rendered);
    // The window really shows it (a screenshot of the X server, not what lancer says it drew).
    Rgb8Image screen = x->screenshot(window);
    write_png((dir / "screenshot.png").string(), screen);
    EXPECT_EQ(screen.width, 96);
    EXPECT_EQ(screen.height, 54);
    expect_like(screen, shown, "screenshot");
    std::string title;
    ASSERT_EQ(x->run("xdotool getwindowname " + window, &title), 0);
    EXPECT_EQ(title.rfind("lancer view | scene.toml | eye (0.00, 3.00, -8.00) | 9/9 samples in ", 0), 0u) << title;
    EXPECT_NE(title.find(" Mrays/s"), std::string::npos) << title;
}

// With adaptive anti-aliasing the view refines in its steps (the first ray of every pixel, then
// each grid) and ends on the picture `lancer render` makes with the same options, byte for byte.
TEST_F(View, AdaptiveAntiAliasingRefinesInStepsToWhatLancerRenderMakes) {
    start({"--aa-threshold", "0.1", "--aa-depth", "2"});
    const Rgb8Image rendered = render(file_camera(), "adaptive", " --aa-threshold 0.1 --aa-depth 2");
    EXPECT_EQ(dump().bytes, rendered.bytes) << test::save_comparison("view-adaptive", dump(), rendered);
    EXPECT_NE(dump().bytes, render(file_camera()).bytes);  // not the full grid's picture
    std::string title;
    ASSERT_EQ(x->run("xdotool getwindowname " + window, &title), 0);
    EXPECT_NE(title.find(" | adaptive, done at step 3/3: "), std::string::npos) << title;
    EXPECT_NE(title.find("% of pixels refined, up to 9)"), std::string::npos) << title;
    const std::string text = log();
    EXPECT_TRUE(std::regex_search(text, std::regex(R"(view: refined 96x54, [0-9.]+ rays/pixel on average \([0-9.]+% of pixels refined, up to 9\) in .* \(3 steps, )")))
        << text;
}

TEST_F(View, RightArrowNTimesMovesTheCameraByNSteps) {
    start();
    const int n = 4;
    keys("Right Right Right Right");
    // The documented step: 5% of the eye-look_at distance along the camera's right.
    CameraSpec expected = file_camera();
    CameraBasis basis = make_camera_basis(expected, 96, 54);
    dvec3 step = glm::normalize(basis.right) * (n * 0.05 * glm::length(expected.look_at - expected.eye));
    expected.eye += step;
    expected.look_at += step;
    ASSERT_TRUE(wait_for_refined_eye(expected.eye)) << log();
    CameraSpec shown_camera = *last_camera(log(), "view: refined");
    EXPECT_TRUE(near(shown_camera.look_at, expected.look_at, 1e-9));
    Rgb8Image rendered = render(expected);
    expect_like(dump(), rendered, "right");
    EXPECT_NE(dump().bytes, render(file_camera(), "unmoved").bytes);  // it did move
}

TEST_F(View, PSavesThePngLancerRenderMakesOfThatView) {
    start();
    keys("Left Left q w");
    keys("p");
    ASSERT_TRUE(wait_for_count("view: saved", 1)) << log();
    std::smatch m;
    std::string text = log();
    ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(view: saved (\S+) \(96x54, 9 rays/pixel\))"))) << text;
    Rgb8Image saved = read_png((dir / m[1].str()).string());
    EXPECT_EQ(m[1].str(), "scene-view-001.png");
    // The camera it reports is the one the keys lead to...
    CameraSpec expected = file_camera();
    for (auto move : {view::CameraMove::Left, view::CameraMove::Left, view::CameraMove::OrbitLeft, view::CameraMove::RollLeft})
        expected = view::apply_move(expected, move, {0, 1, 0});
    CameraSpec reported = *last_camera(text, "view: saved");
    EXPECT_TRUE(near(reported.eye, expected.eye, 1e-12));
    EXPECT_TRUE(near(reported.up, expected.up, 1e-12));
    // ...and the PNG is byte for byte `lancer render` of it (the reported camera reads back exactly).
    Rgb8Image rendered = render(reported);
    EXPECT_EQ(saved.bytes, rendered.bytes) << test::save_comparison("view-p", saved, rendered);
    // A second p never overwrites the first.
    keys("p");
    ASSERT_TRUE(wait_for_count("view: saved", 2)) << log();
    EXPECT_TRUE(fs::exists(dir / "scene-view-002.png"));
}

TEST_F(View, EscapeExitsZeroWithEveryVulkanObjectReleased) {
    start();
    keys("Right Escape");
    expect_clean_exit();
    EXPECT_EQ(log().find("validation"), std::string::npos) << log();
}

TEST_F(View, InterruptExitsZeroToo) {
    start();
    child->interrupt();
    expect_clean_exit();
}

TEST_F(View, MouseDragOrbitsAndTheWheelDollies) {
    start();
    const CameraSpec home = file_camera();
    const double d = glm::length(home.look_at - home.eye);
    ASSERT_EQ(xdotool("mousemove --window " + window + " 40 27 mousedown 1 mousemove_relative --sync 12 0 mouseup 1"), 0);
    ASSERT_TRUE(test::ChildProcess::wait_until([&] {
        auto c = last_camera(log(), "view: refined");
        return c && !near(c->eye, home.eye, 1e-6);
    })) << log();
    CameraSpec dragged = *last_camera(log(), "view: refined");
    EXPECT_NEAR(glm::length(dragged.look_at - dragged.eye), d, 1e-9);
    EXPECT_EQ(dragged.look_at, home.look_at);
    EXPECT_LT(dragged.eye.x, home.eye.x) << "dragging right turns the scene right: the eye goes left";
    EXPECT_NEAR(dragged.eye.y, home.eye.y, 1e-9);
    EXPECT_NEAR(view::roll_degrees(dragged, {0, 1, 0}), 0.0, 1e-9);

    keys("r");
    ASSERT_TRUE(wait_for_refined_eye(home.eye)) << log();
    EXPECT_EQ(dump().bytes, render(home).bytes);  // reset: the file's camera, exactly
    ASSERT_EQ(xdotool("click --delay 20 --repeat 2 4"), 0);  // button 4: the wheel, away from the user
    dvec3 two_in = home.look_at + (home.eye - home.look_at) * (0.9 * 0.9);  // the documented dolly step
    ASSERT_TRUE(wait_for_refined_eye(two_in)) << log();
}

TEST_F(View, HShowsAndHidesTheHelp) {
    start();
    Rgb8Image picture = dump();
    Rgb8Image screen;
    ASSERT_NO_FATAL_FAILURE(show_help(picture, screen));
    // The panel is a veil over the window's top-left corner.
    const std::uint8_t* inside = screen.at(9, 9);
    const std::uint8_t* under = picture.at(9, 9);
    EXPECT_LT(inside[2], under[2]) << "the panel is a dark veil over the sky";
    keys("h");
    ASSERT_TRUE(test::ChildProcess::wait_until([&] { return x->screenshot(window).bytes == picture.bytes; }, seconds(30)));
}

// The bytes of frame k of an animation `lancer render` makes of the test scene plus `animation`.
Rgb8Image render_frame(const fs::path& dir, const std::string& animation, int frame) {
    fs::path scene = dir / "animated.toml", png = dir / ("animated-" + std::to_string(frame) + ".png");
    test::write_file(scene, scene_text(file_camera()) + animation);
    auto r = test::run_lancer("render " + scene.string() + " -q --frames " + std::to_string(frame) + " -o " + png.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_png(png.string());
}

TEST_F(View, FRecordsTheOrbitThroughTheAnimationMachinery) {
    start({"--record-frames", "3"});
    keys("f");
    ASSERT_TRUE(wait_for_count("view: recorded orbit", 1)) << log();
    EXPECT_NE(log().find("view: recording orbit to scene-orbit-1/frame_%d.png: camera_orbit center [0, 0.8, 0]"),
              std::string::npos) << log();
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(fs::exists(dir / ("scene-orbit-1/frame_" + std::to_string(k) + ".png")));
    // The defaults of [animation.camera_orbit] start at the file's eye: the same sequence.
    Rgb8Image expected = render_frame(dir, "[animation]\nframes = 3\ncyclic = true\n[animation.camera_orbit]\n", 1);
    EXPECT_EQ(read_png((dir / "scene-orbit-1/frame_1.png").string()).bytes, expected.bytes);
    if (test::have_program("ffmpeg")) {
        EXPECT_TRUE(fs::exists(dir / "scene-orbit-1.mp4")) << log();
    }
    // Back to the interactive view afterwards: the window answers keys again.
    keys("Right");
    ASSERT_TRUE(wait_for_refined_eye(view::apply_move(file_camera(), view::CameraMove::Right, {0, 1, 0}).eye)) << log();
}

TEST_F(View, LRecordsTheMovingLight) {
    start({"--record-frames", "2"});
    keys("l");
    ASSERT_TRUE(wait_for_count("view: recorded light", 1)) << log();
    Rgb8Image expected = render_frame(
        dir, "[animation]\nframes = 2\ncyclic = true\n[[animation.light_orbit]]\nlight = 0\ncenter = [0, 0.8, 0]\n", 1);
    EXPECT_EQ(read_png((dir / "scene-light-1/frame_1.png").string()).bytes, expected.bytes);
}

TEST_F(View, FAgainStopsARecordingAndEscapeDuringOneQuitsCleanly) {
    start({"--record-frames", "1000"});
    keys("f");
    ASSERT_TRUE(test::ChildProcess::wait_until([&] { return fs::exists(dir / "scene-orbit-1/frame_001.png"); })) << log();
    keys("f");
    ASSERT_TRUE(wait_for_count("view: recording orbit stopped after", 1)) << log();
    keys("l");
    ASSERT_TRUE(test::ChildProcess::wait_until([&] { return fs::exists(dir / "scene-light-1/frame_000.png"); })) << log();
    keys("Escape");
    expect_clean_exit();
}

TEST_F(View, SceneEditsReloadAndBrokenScenesKeepTheLastGoodPicture) {
    start();
    Rgb8Image before = dump();
    CameraSpec moved = file_camera();
    moved.eye.x = 2.0;
    test::write_file(dir / "scene.toml", scene_text(moved));
    ASSERT_TRUE(wait_for_count("scene reloaded", 1)) << log();
    ASSERT_TRUE(wait_for_refined_eye(moved.eye)) << log();  // a changed camera in the file is shown
    EXPECT_EQ(dump().bytes, render(moved).bytes);

    test::write_file(dir / "scene.toml", scene_text(moved) + "\n[[object]]\ntype = \"sphere\"\nradius = -1\ncenter = [0, 0, 0]\n");
    ASSERT_TRUE(wait_for_count("scene error", 1)) << log();
    EXPECT_TRUE(std::regex_search(log(), std::regex(R"(scene\.toml:\d+:\d+: error: sphere radius must be positive)"))) << log();
    EXPECT_TRUE(child->running());
    // Still answering, with the last good scene.
    keys("Right");
    CameraSpec right = view::apply_move(moved, view::CameraMove::Right, {0, 1, 0});
    ASSERT_TRUE(wait_for_refined_eye(right.eye)) << log();
    expect_like(dump(), render(right), "reloaded-right");
    EXPECT_NE(dump().bytes, before.bytes);
}

// A texture is part of the scene: rewriting the image reloads the scene, and the picture is
// `lancer render` of the scene with the new image.
TEST_F(View, TextureEditsReloadTheScene) {
    auto write_texture = [&](std::uint8_t r, std::uint8_t g, std::uint8_t b) {
        write_png((dir / "tex.png").string(), Rgb8Image{1, 1, {r, g, b}});
    };
    write_texture(0, 200, 0);
    std::string scene = scene_text(file_camera());
    const std::string red = "color = [0.9, 0.1, 0.1]";
    scene.replace(scene.find(red), red.size(), "texture = \"tex.png\"");
    test::write_file(dir / "scene.toml", scene);
    start();
    write_texture(0, 0, 230);
    ASSERT_TRUE(wait_for_count("reload: tex.png changed: scene reloaded", 1)) << log();
    ASSERT_TRUE(wait_for_count("view: refined", 2)) << log();
    auto r = test::run_lancer("render " + (dir / "scene.toml").string() + " -q -o " + (dir / "blue.png").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Rgb8Image rendered = read_png((dir / "blue.png").string());
    expect_like(dump(), rendered, "texture-reloaded");
    const std::uint8_t* sphere = rendered.at(37, 20);  // on the textured sphere
    EXPECT_GT(sphere[2], sphere[1]) << "the new, blue texture is not shown";
}

TEST_F(View, ShaderEditsReloadAndCompileErrorsKeepTheLastGoodPicture) {
    copy_shaders();
    start({"--shaders", "shaders"});
    fs::path trace = dir / "shaders/trace.comp";
    std::string source = test::read_file(trace);
    const std::string miss = "color += b.weight * frame.background.rgb;";
    ASSERT_NE(source.find(miss), std::string::npos) << "the test edits this line of trace.comp";
    std::string magenta = source;
    magenta.replace(magenta.find(miss), miss.size(), "color += b.weight * vec3(1.0, 0.0, 1.0);");
    int refined = test::count_occurrences(log(), "view: refined");
    test::write_file(trace, magenta);
    ASSERT_TRUE(wait_for_count("reload: shaders compiled", 1)) << log();
    ASSERT_TRUE(wait_for_count("view: refined", refined + 1)) << log();
    Rgb8Image img = dump();
    EXPECT_EQ(img.at(0, 0)[0], 255);
    EXPECT_EQ(img.at(0, 0)[1], 0);
    EXPECT_EQ(img.at(0, 0)[2], 255);

    fs::path shade = dir / "shaders/shade.glsl";
    std::string good_shade = test::read_file(shade);
    test::write_file(shade, good_shade + "this is not glsl(\n");
    ASSERT_TRUE(wait_for_count("compile failed", 1)) << log();
    EXPECT_NE(log().find("shaders/shade.glsl:"), std::string::npos) << log();
    EXPECT_TRUE(child->running());
    refined = test::count_occurrences(log(), "view: refined");
    keys("Right");  // still magenta: the last good shaders
    ASSERT_TRUE(wait_for_count("view: refined", refined + 1)) << log();
    EXPECT_EQ(dump().at(0, 0)[1], 0);
}

// One flat bicubic patch standing on the floor, facing the camera, `size` wide from x: a .bpt file.
std::string standing_patch(double x, double size) {
    std::string s = "1\n3 3\n";
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            s += std::to_string(x + size * i / 3.0) + " " + std::to_string(size * j / 3.0) + " -2\n";
    return s;
}

// The scene is its file, whatever its name, and the files it references: editing either
// reloads it (here with a shader directory, so that nothing is taken for a shader).
TEST_F(View, EditsOfTheSceneAndOfTheFilesItReferencesReloadIt) {
    copy_shaders();
    const std::string patch = "[[object]]\ntype = \"bezier\"\nfile = \"panel.bpt\"\nmaterial = \"red\"\n";
    test::write_file(dir / "panel.bpt", standing_patch(-3, 1.5));
    test::write_file(dir / "panel.scene", scene_text(file_camera()) + patch);
    start({"--shaders", "shaders"}, "panel.scene");
    Rgb8Image before = dump();
    auto rendered = [&] {
        auto r = test::run_lancer("render " + (dir / "panel.scene").string() + " -q -o " + (dir / "panel.png").string());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return read_png((dir / "panel.png").string());
    };

    int refined = test::count_occurrences(log(), "view: refined");
    test::write_file(dir / "panel.bpt", standing_patch(0.5, 2));
    ASSERT_TRUE(wait_for_count("reload: panel.bpt changed: scene reloaded", 1)) << log();
    ASSERT_TRUE(wait_for_count("view: refined", refined + 1)) << log();
    EXPECT_NE(dump().bytes, before.bytes);
    EXPECT_EQ(dump().bytes, rendered().bytes);

    CameraSpec moved = file_camera();
    moved.eye.x = 2.0;
    test::write_file(dir / "panel.scene", scene_text(moved) + patch);
    ASSERT_TRUE(wait_for_count("reload: panel.scene changed: scene reloaded", 1)) << log();
    ASSERT_TRUE(wait_for_refined_eye(moved.eye)) << log();
    EXPECT_EQ(dump().bytes, rendered().bytes);
    EXPECT_EQ(log().find("compil"), std::string::npos) << log();
}

// The scene is edited to reference a broken patch file: that file is watched from then on, so
// fixing it (not touching the scene again) shows the patch.
TEST_F(View, ABrokenFileTheSceneBeginsToReferenceIsWatchedUntilFixed) {
    start();
    test::write_file(dir / "panel.bpt", "1\n3 3\n0 0 0\n");  // 1 of 16 points
    test::write_file(dir / "scene.toml", scene_text(file_camera()) +
                                             "[[object]]\ntype = \"bezier\"\nfile = \"panel.bpt\"\nmaterial = \"red\"\n");
    ASSERT_TRUE(wait_for_count("reload: scene.toml changed: scene error", 1)) << log();
    int refined = test::count_occurrences(log(), "view: refined");
    test::write_file(dir / "panel.bpt", standing_patch(0.5, 2));
    ASSERT_TRUE(wait_for_count("reload: panel.bpt changed: scene reloaded", 1)) << log();
    ASSERT_TRUE(wait_for_count("view: refined", refined + 1)) << log();
    auto r = test::run_lancer("render " + (dir / "scene.toml").string() + " -q -o " + (dir / "panel.png").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(dump().bytes, read_png((dir / "panel.png").string()).bytes);
}

// A burst that breaks a shader and edits the scene: the new scene is shown all the same, drawn
// with the last good shaders.
TEST_F(View, ABrokenShaderInTheSameBurstAsASceneEditStillShowsTheScene) {
    copy_shaders();
    start({"--shaders", "shaders"});
    fs::path shade = dir / "shaders/shade.glsl";
    CameraSpec moved = file_camera();
    moved.eye.x = 2.0;
    test::write_file(shade, test::read_file(shade) + "this is not glsl(\n");
    test::write_file(dir / "scene.toml", scene_text(moved));
    ASSERT_TRUE(wait_for_count("compile failed", 1)) << log();
    ASSERT_TRUE(wait_for_count("scene reloaded", 1)) << log();
    ASSERT_TRUE(wait_for_refined_eye(moved.eye)) << log();
    EXPECT_EQ(dump().bytes, render(moved).bytes);
}

// In a window too small for the key table, the help is a note that fits, not a table cut off.
TEST_F(View, TheHelpFitsASmallWindow) {
    start({"--width", "160", "--height", "90"});
    Rgb8Image picture = dump();
    ASSERT_EQ(picture.width, 160);
    Rgb8Image screen;
    ASSERT_NO_FATAL_FAILURE(show_help(picture, screen));
    ASSERT_EQ(screen.width, 160);
    ASSERT_EQ(screen.height, 90);
    // The panel is where the screen differs from the picture: all of it, with its four edges,
    // inside the window.
    int min_x = screen.width, min_y = screen.height, max_x = -1, max_y = -1;
    for (int y = 0; y < screen.height; ++y)
        for (int x0 = 0; x0 < screen.width; ++x0)
            if (!std::equal(screen.at(x0, y), screen.at(x0, y) + 3, picture.at(x0, y))) {
                min_x = std::min(min_x, x0), max_x = std::max(max_x, x0);
                min_y = std::min(min_y, y), max_y = std::max(max_y, y);
            }
    EXPECT_GT(min_x, 0);
    EXPECT_GT(min_y, 0);
    EXPECT_LT(max_x, screen.width - 1) << "the panel runs off the window's right edge";
    EXPECT_LT(max_y, screen.height - 1) << "the panel runs off the window's bottom edge";
}

// Errors the viewer meets before it opens a window: one line, exit code 2.
void expect_user_error(const std::string& args, const std::string& env, const std::string& message) {
    auto r = test::run_lancer(args, env);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(test::count_occurrences(r.err, "\n"), 1) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
}

TEST(ViewErrors, AreOneLineAndExitCode2) {
    std::string scene = test::source_path("scenes/seed.toml");
    expect_user_error("view " + scene, "DISPLAY= WAYLAND_DISPLAY=", "cannot open a window: no display");
    expect_user_error("view " + scene, "DISPLAY=:65000 WAYLAND_DISPLAY=", "cannot open a window on display ':65000'");
    expect_user_error("view " + test::source_path("tests/data/bad/negative_radius.toml"), "DISPLAY=:0",
                      "sphere radius must be positive");
    expect_user_error("view " + scene + " --backend cpu", "", "GPU only");
    expect_user_error("view " + scene + " --device nonexistent-gpu", "DISPLAY=", "no Vulkan device matches");
    expect_user_error("view " + scene + " --dump-frame /nonexistent/dump.png", "", "does not exist");
    expect_user_error("view " + scene + " --frame 2", "", "--frame: the scene has no [animation]");
}

}  // namespace
}  // namespace lancer

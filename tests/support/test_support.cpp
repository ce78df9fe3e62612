#include "support/test_support.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "cpu/cpu_renderer.hpp"
#include "scene/animation.hpp"
#include "scene/load_scene.hpp"
#include "scene/placement.hpp"

namespace lancer::test {

std::string source_path(const std::string& relative) { return std::string(LANCER_SOURCE_DIR) + "/" + relative; }

std::string output_dir() {
    std::filesystem::create_directories(LANCER_TEST_OUTPUT_DIR);
    return LANCER_TEST_OUTPUT_DIR;
}

// ctest runs each test in its own process, in parallel: a directory named only by the caller
// would be emptied by one test while another reads it, so it lives under the running test's name.
std::string fresh_dir(const std::string& name) {
    std::string dir = output_dir() + "/" + name;
    if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info())
        dir = output_dir() + "/" + info->test_suite_name() + "." + info->name() + "/" + name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::string listing(const std::string& dir) {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    std::string out;
    for (const auto& n : names) out += n + " ";
    return out;
}

namespace {
std::unique_ptr<GpuRenderer> g_renderer;
}

GpuRenderer& gpu_renderer() {
    if (!g_renderer) g_renderer = std::make_unique<GpuRenderer>(gpu::ContextOptions{"", /*validation=*/true});
    return *g_renderer;
}

void release_gpu_renderer() { g_renderer.reset(); }

FloatImage render_on(Backend backend, const Scene& scene) {
    if (backend == Backend::Gpu) return gpu_renderer().render(scene, {});
    return CpuRenderer().render(scene, {});
}

std::string small_animation() { return source_path("tests/data/anim/small.toml"); }

void PrintTo(const RejectedCommand& c, std::ostream* os) { *os << c.name; }

const char* backend_name(Backend backend) { return backend == Backend::Gpu ? "gpu" : "cpu"; }

Scene scene_from_text(const std::string& toml) { return parse_scene(toml, "inline.toml"); }

Scene shipped_scene(const std::string& name, int width, int height, int samples) {
    Scene scene = load_scene(source_path("scenes/" + name + ".toml"));
    scene.render.width = width;
    scene.render.height = height;
    if (samples > 0) scene.render.samples = samples;
    return scene;
}

std::string save_comparison(const std::string& name, const Rgb8Image& a, const Rgb8Image& b) {
    std::string dir = output_dir() + "/" + name;
    std::filesystem::create_directories(dir);
    write_png(dir + "/a.png", a);
    write_png(dir + "/b.png", b);
    write_png(dir + "/diff.png", difference_image(a, b));
    return dir;
}

Scene moved_scene(Scene scene, const glm::dvec3& offset) {
    for (Object& o : scene.objects) translate(o, offset);
    for (Light& l : scene.lights) l.position += offset;
    scene.camera.eye += offset;
    scene.camera.look_at += offset;
    return scene;
}

void expect_same_picture(const std::string& name, const Rgb8Image& a, const Rgb8Image& b) {
    constexpr double kMinPsnr = 40.0;
    constexpr double kMaxFractionOver = 0.001;
    constexpr int kThreshold = 4;
    ImageDiff d = compare_images(a, b, kThreshold);
    testing::Test::RecordProperty(name + "_psnr_db", std::to_string(d.psnr_db));
    if (d.psnr_db >= kMinPsnr && d.fraction_over <= kMaxFractionOver) return;
    std::string dir = save_comparison(name, a, b);
    ADD_FAILURE() << name << ": PSNR " << d.psnr_db << " dB, " << d.fraction_over * 100 << "% of pixels off by more than "
                  << kThreshold << "/255 (largest " << d.max_abs << "/255); images in " << dir;
}

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_file(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::trunc);
    out << text;
}

int count_occurrences(const std::string& text, const std::string& what) {
    int n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

std::vector<std::string> scene_files() {
    std::vector<std::string> paths;
    for (const auto& e : std::filesystem::directory_iterator(source_path("scenes")))
        if (e.path().extension() == ".toml") paths.push_back(e.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

CommandResult run_lancer(const std::string& args, const std::string& env) {
    std::string base = output_dir() + "/cli-" + std::to_string(::getpid());
    // Every GPU run is validated: any validation message turns exit code 0 into 1.
    std::string command = "LANCER_VALIDATION=1 " + env + " " + LANCER_EXE + " " + args + " >" + base + ".out 2>" + base + ".err </dev/null";
    int status = std::system(command.c_str());
    CommandResult r{WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), read_file(base + ".out"),
                    read_file(base + ".err")};
    std::filesystem::remove(base + ".out");
    std::filesystem::remove(base + ".err");
    return r;
}

void expect_scene_error(const std::string& toml, int line, int column, const std::string& message) {
    try {
        scene_from_text(toml);
        ADD_FAILURE() << "loaded:\n" << toml;
    } catch (const SceneError& e) {
        EXPECT_EQ(e.where().line, line) << e.what() << "\n" << toml;
        if (column >= 0) {
            EXPECT_EQ(e.where().column, column) << e.what() << "\n" << toml;
        }
        EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
}

void expect_refused(std::string args, const std::string& env, const std::string& message, const std::string& out) {
    if (auto at = args.find("OUT"); at != std::string::npos) args.replace(at, 3, out);
    const CommandResult r = run_lancer(args, env);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind(message, 0), 0u) << "stderr was: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line expected: " << r.err;
    EXPECT_FALSE(file_exists(out));
}

bool file_exists(const std::string& path) { return std::filesystem::exists(path); }

}  // namespace lancer::test

#pragma once
// Shared helpers for lancer's tests: paths, a validated GPU renderer shared by all tests of a
// process, image comparison that leaves evidence behind on failure, and running the CLI.
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/diff.hpp"
#include "scene/scene.hpp"

namespace lancer::test {

std::string source_path(const std::string& relative);  // under the repository root
std::string output_dir();                               // build/test-output, created on demand
std::string fresh_dir(const std::string& name);         // output_dir()/<running test>/name, emptied or created
// The names in `dir`, sorted and space-separated: a temporary file left behind shows up here.
std::string listing(const std::string& dir);

// One GPU renderer per test process (pipeline JIT and device creation are paid once), created
// with VK_LAYER_KHRONOS_validation enabled.
GpuRenderer& gpu_renderer();
// Destroys it (all Vulkan objects), so teardown messages of the validation layer are counted too.
void release_gpu_renderer();

// The two renderers, for tests that check both against the same expected values.
enum class Backend { Gpu, Cpu };
// How far a pixel may be from a value computed in double when it is compared on both backends:
// the GPU works in float.
inline constexpr float kBackendTolerance = 2e-5f;
inline constexpr double kDegree = kPi / 180.0;
FloatImage render_on(Backend backend, const Scene& scene);  // the shared GPU renderer, or a CpuRenderer
const char* backend_name(Backend backend);                   // "gpu" or "cpu", for test names

// tests/data/anim/small.toml: an animation of 6 frames at 10 fps, 48x27.
std::string small_animation();
inline constexpr int kSmallAnimationFrames = 6;

// A command line that must be refused with one clear line: the test's name, its arguments and
// environment, and the start of the line expected on stderr.
struct RejectedCommand {
    std::string name;
    std::string args;
    std::string env;
    std::string message;
};
void PrintTo(const RejectedCommand& c, std::ostream* os);

// Loads a scene from text (for tests that build scenes inline).
Scene scene_from_text(const std::string& toml);
// scenes/NAME.toml at a test's image size; `samples` 0 keeps the scene's own.
Scene shipped_scene(const std::string& name, int width, int height, int samples = 0);
// The scene moved by `offset`, objects, lights and camera together: the same picture.
Scene moved_scene(Scene scene, const glm::dvec3& offset);

// Writes a.png, b.png and diff.png under output_dir()/name and returns the directory.
std::string save_comparison(const std::string& name, const Rgb8Image& a, const Rgb8Image& b);

// The image tests' metric: PSNR >= 40 dB over the 8-bit sRGB images and at most 0.1% of pixels
// with a channel off by more than 4/255. The GPU works in float, the reference in double: they
// differ only where a sample ray falls within rounding distance of an edge (silhouette, shadow
// boundary, checker line), flipping 1 of the samples and moving that pixel by a fraction of the
// local contrast. Such pixels are rare (well under 0.1% at 9 spp) and barely move the PSNR; a
// real shading or geometry bug moves whole regions by several levels and fails both bounds.
// On failure, adds a test failure naming `name` and saves the two images and their difference.
void expect_same_picture(const std::string& name, const Rgb8Image& a, const Rgb8Image& b);

struct CommandResult {
    int exit_code;
    std::string out;
    std::string err;
};
// Runs `lancer <args>` through the shell with extra environment assignments (e.g. "VK_ICD_FILENAMES=x").
CommandResult run_lancer(const std::string& args, const std::string& env = "");
// `lancer <args>` (with "OUT" in them replaced by `out`) must be refused as the CLI promises: exit
// code 2, one line on stderr that begins with `message`, and no file at `out`.
void expect_refused(std::string args, const std::string& env, const std::string& message, const std::string& out);
// Loading the scene `toml` must fail with a SceneError at `line` (and `column`, unless it is -1)
// whose message contains `message`.
void expect_scene_error(const std::string& toml, int line, int column, const std::string& message);

bool file_exists(const std::string& path);
std::string read_file(const std::string& path);
void write_file(const std::string& path, const std::string& text);  // replaces it
// How many times `what` occurs in `text` (log lines, for instance).
int count_occurrences(const std::string& text, const std::string& what);

// Every scene shipped in scenes/, sorted, for tests that run on all of them.
std::vector<std::string> scene_files();

}  // namespace lancer::test

#include "cli/render_options.hpp"

#include <cctype>
#include <filesystem>

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include "cpu/cpu_renderer.hpp"
#include "gpu/context.hpp"
#include "gpu/gpu_renderer.hpp"
#include "gpu/shader_compiler.hpp"
#include "scene/limits.hpp"
#include "scene/load_scene.hpp"

namespace lancer {

namespace {

// lancer writes PNG files only: a name without .png (or an empty one) would be a surprise later.
std::string check_png_name(std::string& name) {
    if (name.empty()) return "the output file name is empty";
    std::string ext = std::filesystem::path(name).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".png") return "'" + name + "': lancer writes PNG images, so the name must end in .png";
    return {};
}

// CLI::Range lets NaN through (every comparison with it is false).
std::string check_aa_threshold(std::string& text) {
    double v = 0.0;
    if (!CLI::detail::lexical_cast(text, v)) return "'" + text + "' is not a number";
    if (!(v >= 0.0 && v <= 3.0)) return "must be in [0, 3], not " + text;
    return "";
}

}  // namespace

void add_render_options(CLI::App& cmd, RenderOptions& o) {
    cmd.add_option("scene", o.scene, "Scene file (TOML)")->required();
    cmd.add_option("-o,--output", o.output,
                   "Output PNG, or for an animation a frame pattern such as NAME_%03d.png "
                   "(default: the scene's name, here)")
        ->check(CLI::Validator(check_png_name, "FILE.png"));
    cmd.add_option("--width", o.width, "Image width in pixels (overrides [render] width)")
        ->check(CLI::Range(1, limits::kMaxImageSide));
    cmd.add_option("--height", o.height, "Image height in pixels (overrides [render] height)")
        ->check(CLI::Range(1, limits::kMaxImageSide));
    cmd.add_option("--samples", o.samples, "N: an N x N grid of rays per pixel (default 3 = 9 rays)")
        ->check(CLI::Range(1, limits::kMaxSamples));
    cmd.add_option("--aa-threshold", o.aa_threshold,
                   "T: adaptive anti-aliasing as POV-Ray's +AM1 +A<T>: one ray per pixel, the full N x N grid where a "
                   "pixel differs from a neighbour by more than T (|dr|+|dg|+|db| of the sRGB colours, 0..3; POV-Ray's default 0.3)")
        ->check(CLI::Validator(check_aa_threshold, "T in [0, 3]"));
    cmd.add_option("--max-depth", o.max_depth, "Levels of reflection and refraction (default 5)")->check(CLI::Range(0, limits::kMaxDepth));
    cmd.add_option("--backend", o.backend, "gpu (Vulkan compute, default) or cpu (reference renderer)")
        ->check(CLI::IsMember({"gpu", "cpu"}));
    cmd.add_option("--device", o.device, "Vulkan device: index or part of its name (see --list-devices)");
    cmd.add_option("--shaders", o.shader_dir,
                   "Compile the tracer at run time from this shader directory instead of the built-in one");
    cmd.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
}

Scene load_scene_with_overrides(const RenderOptions& o) {
    Scene scene = load_scene(o.scene);
    RenderSettings& r = scene.render;
    if (o.width) r.width = *o.width;
    if (o.height) r.height = *o.height;
    if (o.samples) r.samples = *o.samples;
    if (o.max_depth) r.max_depth = *o.max_depth;
    if (o.aa_threshold) r.aa_threshold = *o.aa_threshold;
    if (static_cast<long long>(r.width) * r.height > limits::kMaxImagePixels)
        throw UserError(fmt::format("{}x{} exceeds the limit of {} pixels", r.width, r.height, limits::kMaxImagePixels));
    return scene;
}

std::string output_path(const RenderOptions& o) {
    if (!o.output.empty()) return o.output;
    return std::filesystem::path(o.scene).stem().string() + ".png";
}

void check_output_writable(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw UserError("cannot write '" + path + "': it is a directory");
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    if (!fs::is_directory(dir, ec))
        throw UserError("cannot write '" + path + "': directory '" + dir.string() + "' does not exist");
    if (::access(dir.c_str(), W_OK) != 0)
        throw UserError("cannot write '" + path + "': directory '" + dir.string() + "' is not writable");
    // Refused before rendering, not after (the temporary file's name is shortened to fit, the
    // destination's cannot be).
    long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
    std::size_t length = fs::path(path).filename().string().size();
    if (name_max > 0 && length > static_cast<std::size_t>(name_max))
        throw UserError(fmt::format("cannot write '{}': its name is {} bytes long, and the file system allows {}", path,
                                    length, name_max));
}

std::unique_ptr<Renderer> make_renderer(const RenderOptions& o) {
    if (o.backend == "cpu") {
        if (!o.shader_dir.empty()) throw UserError("--shaders needs the gpu backend");
        return std::make_unique<CpuRenderer>();
    }
    auto gpu = std::make_unique<GpuRenderer>(gpu::ContextOptions{o.device, gpu::validation_requested_by_environment()});
    if (!o.shader_dir.empty()) {
        if (!std::filesystem::is_directory(o.shader_dir))
            throw UserError("--shaders: '" + o.shader_dir + "' is not a directory");
        gpu->use_shaders(gpu::directory_tree(o.shader_dir), o.shader_dir);
    }
    return gpu;
}

long peak_rss_mib() {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024;  // KiB on Linux
}

std::string camera_rays_summary(int samples, long long pixels, long long refined) {
    const int grid = samples * samples;
    if (refined < 0) return fmt::format("{} rays/pixel", grid);
    const double share = pixels > 0 ? double(refined) / double(pixels) : 0.0;
    return fmt::format("{:.2f} rays/pixel on average ({:.1f}% of pixels refined to {})", 1.0 + share * grid,
                       100.0 * share, grid);
}

}  // namespace lancer

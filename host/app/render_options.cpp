#include "app/render_options.hpp"

#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include "app/option_checks.hpp"
#include "core/file_reading.hpp"
#include "core/sha256.hpp"
#include "core/version.hpp"
#include "cpu/cpu_renderer.hpp"
#include "gpu/vulkan/context.hpp"
#include "gpu/gpu_renderer.hpp"
#include "gpu/shaders/shader_compiler.hpp"
#include "scene/limits.hpp"
#include "scene/animation.hpp"
#include "scene/load_scene.hpp"

namespace lancer {

namespace {

// lancer writes PNG, OpenEXR and PFM files: any other name (or an empty one) would be a surprise later.
std::string check_image_name(std::string& name) {
    if (name.empty()) return "the output file name is empty";
    if (!image_format_of(name))
        return "'" + name + "': lancer writes PNG, OpenEXR and PFM images, so the name must end in .png, .exr or .pfm";
    return {};
}

// A whole string of decimal digits as a non-negative int; nullopt for anything else (a sign,
// spaces, "0x10", a value beyond int).
std::optional<int> pass_number(std::string_view text) {
    int value = 0;
    if (text.empty() || text.front() < '0' || text.front() > '9') return std::nullopt;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

// "A-B" (0-based, inclusive) or "N" -> first, count; nullopt when malformed.
std::optional<std::pair<int, int>> parse_range(const std::string& text) {
    const std::size_t dash = text.find('-');
    std::optional<int> a = pass_number(std::string_view(text).substr(0, dash));
    std::optional<int> b = dash == std::string::npos ? a : pass_number(std::string_view(text).substr(dash + 1));
    if (!a || !b || *b < *a) return std::nullopt;
    return std::pair{*a, *b - *a + 1};
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
        ->check(CLI::Validator(check_image_name, "FILE.png|.exr|.pfm"));
    cmd.add_option("--width", o.width, "Image width in pixels (overrides [render] width)")
        ->transform(decimal_integer())->check(CLI::Range(1, limits::kMaxImageSide));
    cmd.add_option("--height", o.height, "Image height in pixels (overrides [render] height)")
        ->transform(decimal_integer())->check(CLI::Range(1, limits::kMaxImageSide));
    cmd.add_option("--samples", o.samples, "N: an N x N grid of rays per pixel (default 3 = 9 rays)")
        ->transform(decimal_integer())->check(CLI::Range(1, limits::kMaxSamples));
    cmd.add_option("--aa-threshold", o.aa_threshold,
                   "T: adaptive anti-aliasing as POV-Ray's +A<T>: one ray per pixel, finer grids up to N x N where a "
                   "pixel differs from a neighbour by more than T (|dr|+|dg|+|db| of the sRGB colours, 0..3; POV-Ray's default 0.3)")
        ->check(CLI::Validator(check_aa_threshold, "T in [0, 3]"));
    cmd.add_option("--aa-depth", o.aa_depth,
                   "R: adaptive refinements, each on a finer grid up to N x N (default 1: straight to N x N, POV-Ray's +AM1)")
        ->transform(decimal_integer())->check(CLI::Range(1, limits::kMaxSamples - 1));
    cmd.add_option("--aa-method", o.aa_method,
                   "What sends a refined pixel on to the next grid: neighbours (default; its colour against its "
                   "neighbours') or spread (its own samples', as POV-Ray's +AM2)")
        ->check(CLI::IsMember({"neighbours", "spread"}));
    cmd.add_option("--max-depth", o.max_depth, "Levels of reflection and refraction (default 5)")
        ->transform(decimal_integer())
        ->check(CLI::Range(0, limits::kMaxDepth));
    cmd.add_option("--exposure", o.exposure, "Stops: the PNG shows the image times 2^EV (overrides [render] exposure; -64 to 64)")
        ->check(exposure_stops());
    cmd.add_option("--tone", o.tone, "Tone curve for the PNG: clamp, reinhard or aces (overrides [render] tone)")
        ->check(CLI::IsMember({"clamp", "reinhard", "aces"}));
    cmd.add_option("--photons", o.photons, "Photon mapping: photons shot per pass (switches it on; overrides [photons] count)")
        ->transform(decimal_integer())->check(CLI::Range(1, limits::kMaxPhotonsPerPass));
    cmd.add_option("--passes", o.passes, "Photon mapping: passes whose estimates are averaged (overrides [photons] passes)")
        ->transform(decimal_integer())->check(CLI::Range(1, limits::kMaxPhotonPasses));
    cmd.add_option("--pass-range", o.pass_range,
                   "Photon mapping: render only passes A-B (0-based) of the whole, for one machine of a farm; "
                   "combine the parts with lancer combine")
        ->check(not_empty("expected A-B or N (0-based pass numbers)"));
    cmd.add_option("--backend", o.backend, "gpu (Vulkan compute, default) or cpu (reference renderer)")
        ->check(CLI::IsMember({"gpu", "cpu"}));
    cmd.add_option("--device", o.device, "Vulkan device: index or part of its name (see --list-devices)");
    cmd.add_option("--shaders", o.shader_dir,
                   "Compile the tracer at run time from this shader directory instead of the built-in one");
    cmd.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
}

Scene scene_for_frame(const RenderOptions& o, const Scene& loaded, int k) {
    const double time = frame_time(*loaded.animation, k);
    if (!loaded.depends_on_time) return scene_at(loaded, time);
    const Scene again = load_scene_with_overrides(o, SceneTime{time, k});
    if (!again.animation || again.animation->frames != loaded.animation->frames)
        throw UserError(fmt::format("{}: [animation] frames depends on clock or frame: the frames would change as they are rendered",
                                    o.scene));
    return scene_at(again, time);
}

Scene load_scene_with_overrides(const RenderOptions& o, SceneTime time) {
    Scene scene = load_scene(o.scene, time);
    RenderSettings& r = scene.render;
    if (o.width) r.width = *o.width;
    if (o.height) r.height = *o.height;
    if (o.samples) r.samples = *o.samples;
    if (o.max_depth) r.max_depth = *o.max_depth;
    if (o.exposure) r.tone.exposure = *o.exposure;
    if (o.tone == "clamp") r.tone.tone = Tone::Clamp;
    if (o.tone == "reinhard") r.tone.tone = Tone::Reinhard;
    if (o.tone == "aces") r.tone.tone = Tone::Aces;
    if (o.photons) {
        if (!scene.photons) scene.photons = photon_defaults(scene.camera);
        scene.photons->count = *o.photons;
    }
    if ((o.passes || !o.pass_range.empty()) && !scene.photons)
        throw UserError(std::string(o.passes ? "--passes" : "--pass-range") +
                        ": the scene does not use photon mapping (add a [photons] table, or --photons N)");
    if (o.passes) scene.photons->passes = *o.passes;
    if (!o.pass_range.empty()) {
        auto range = parse_range(o.pass_range);
        if (!range) throw UserError("--pass-range " + o.pass_range + ": expected A-B or N (0-based pass numbers)");
        if (range->first + range->second > scene.photons->passes)
            throw UserError(fmt::format("--pass-range {}: the render has passes 0-{}", o.pass_range, scene.photons->passes - 1));
        scene.photons->first_pass = range->first;
        scene.photons->pass_count = range->second;
    }
    if (scene.photons) check_photon_lights(scene);  // --photons on a scene whose lights have no power
    if (o.aa_threshold) r.aa_threshold = *o.aa_threshold;
    if (o.aa_depth) r.aa_depth = *o.aa_depth;
    if (!o.aa_method.empty()) r.aa_method = o.aa_method == "spread" ? AaMethod::Spread : AaMethod::Neighbours;
    if (auto problem = adaptive_settings_problem(r, o.aa_depth.has_value(), !o.aa_method.empty()))
        throw UserError(problem->message + " (the scene's [render] with the command line's options)");
    if (scene.photons && r.aa_threshold)
        throw UserError("adaptive anti-aliasing (--aa-threshold, [render] aa_threshold) does not combine with photon "
                        "mapping, which traces one camera ray per pixel per pass");
    if (static_cast<long long>(r.width) * r.height > limits::kMaxImagePixels)
        throw UserError(fmt::format("{}x{} exceeds the limit of {} pixels", r.width, r.height, limits::kMaxImagePixels));
    return scene;
}

ExrInfo image_info(const Scene& scene) {
    ExrInfo info;
    info.tone = scene.render.tone;
    if (scene.photons) {
        info.first_pass = scene.photons->first_pass;
        info.passes = scene.photons->last_pass() - scene.photons->first_pass;
        info.total_passes = scene.photons->passes;
    }
    return info;
}

namespace {

std::string vec_text(const dvec3& v) { return fmt::format("({}, {}, {})", v.x, v.y, v.z); }

}  // namespace

std::vector<std::string> scene_inputs(const Scene& scene) {
    std::vector<std::string> files{scene.path};
    files.insert(files.end(), scene.dependencies.begin(), scene.dependencies.end());
    return files;
}

std::string scene_files_hash(const Scene& scene) {
    Sha256 hash;  // the same on every machine and build, as lancer's cache keys
    for (const std::string& file : scene_inputs(scene)) {
        std::error_code ec;
        // A FIFO or device was read once by the loader; reading it again could block for ever.
        if (!std::filesystem::is_regular_file(file, ec)) {
            hash.add_field("not a regular file: " + file);
            continue;
        }
        FileText text = read_file(file, std::size_t(1) << 31);
        hash.add_field(text.text);
        if (!text.complete) hash.add_field("larger than 2 GiB");
    }
    return to_hex(hash.finish());
}

std::string render_settings_text(const Scene& scene, const RenderOptions& o) {
    const RenderSettings& r = scene.render;
    std::string text = fmt::format("lancer {}\nbackend {}\n", kVersion, o.backend);
    if (!o.shader_dir.empty()) text += "shaders " + o.shader_dir + "\n";
    text += fmt::format("size {}x{}\nsamples {}\nmax_depth {}\n", r.width, r.height, r.samples, r.max_depth);
    if (r.aa_threshold)
        text += fmt::format("adaptive threshold {} depth {} method {}\n", *r.aa_threshold, r.aa_depth,
                            r.aa_method == AaMethod::Spread ? "spread" : "neighbours");
    const CameraSpec& c = scene.camera;
    text += fmt::format("camera eye {} look_at {} up {} fov {}\n", vec_text(c.eye), vec_text(c.look_at), vec_text(c.up), c.fov_deg);
    if (const auto& p = scene.photons)
        text += fmt::format("photons {} per pass, {} passes, radii {} {}, alpha {}, seed {}, max_bounces {}\n", p->count,
                            p->passes, p->caustic_radius, p->global_radius, p->alpha, p->seed, p->max_bounces);
    return text;
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

}  // namespace lancer

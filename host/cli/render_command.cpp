// `lancer render`: scene file -> PNG.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <sys/resource.h>
#include <unistd.h>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "cpu/cpu_renderer.hpp"
#include "gpu/context.hpp"
#include "gpu/gpu_renderer.hpp"
#include "scene/limits.hpp"
#include "scene/load_scene.hpp"

namespace lancer {

CLI::App* add_render_command(CLI::App& app, RenderOptions& o) {
    CLI::App* cmd = app.add_subcommand("render", "Render a scene file to a PNG");
    cmd->add_option("scene", o.scene, "Scene file (TOML)")->required();
    cmd->add_option("-o,--output", o.output, "Output PNG (default: the scene's name with .png, here)");
    cmd->add_option("--width", o.width, "Image width in pixels (overrides [render] width)")
        ->check(CLI::Range(1, limits::kMaxImageSide));
    cmd->add_option("--height", o.height, "Image height in pixels (overrides [render] height)")
        ->check(CLI::Range(1, limits::kMaxImageSide));
    cmd->add_option("--samples", o.samples, "N: an N x N grid of rays per pixel (default 3 = 9 rays)")
        ->check(CLI::Range(1, limits::kMaxSamples));
    cmd->add_option("--max-depth", o.max_depth, "Reflection bounces (default 5)")->check(CLI::Range(0, limits::kMaxDepth));
    cmd->add_option("--backend", o.backend, "gpu (Vulkan compute, default) or cpu (reference renderer)")
        ->check(CLI::IsMember({"gpu", "cpu"}));
    cmd->add_option("--device", o.device, "Vulkan device: index or part of its name (see --list-devices)");
    cmd->add_flag("--list-devices", o.list_devices, "List the Vulkan devices and exit");
    cmd->add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
    return cmd;
}

int list_devices() {
    auto devices = gpu::Context::list_devices();
    if (devices.empty()) std::printf("no Vulkan devices\n");
    for (const auto& d : devices) std::printf("%u: %s (%s, %s)\n", d.index, d.name.c_str(), d.type.c_str(), d.driver.c_str());
    return 0;
}

namespace {

void apply_overrides(const RenderOptions& o, RenderSettings& r) {
    if (o.width) r.width = *o.width;
    if (o.height) r.height = *o.height;
    if (o.samples) r.samples = *o.samples;
    if (o.max_depth) r.max_depth = *o.max_depth;
    if (static_cast<long long>(r.width) * r.height > limits::kMaxImagePixels)
        throw UserError(fmt::format("{}x{} exceeds the limit of {} pixels", r.width, r.height, limits::kMaxImagePixels));
}

long peak_rss_mib() {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024;  // ru_maxrss is in KiB on Linux
}

std::string default_output(const std::string& scene) {
    return std::filesystem::path(scene).stem().string() + ".png";
}

// Fails early, before minutes of rendering, when the PNG could not be written anyway.
void check_output_writable(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw UserError("cannot write '" + path + "': it is a directory");
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    if (!fs::is_directory(dir, ec)) throw UserError("cannot write '" + path + "': directory '" + dir.string() + "' does not exist");
    if (::access(dir.c_str(), W_OK) != 0) throw UserError("cannot write '" + path + "': directory '" + dir.string() + "' is not writable");
}

}  // namespace

int run_render(const RenderOptions& o) {
    Scene scene = load_scene(o.scene);
    apply_overrides(o, scene.render);
    std::string output = o.output.empty() ? default_output(o.scene) : o.output;
    check_output_writable(output);

    std::unique_ptr<Renderer> renderer;
    if (o.backend == "cpu") {
        renderer = std::make_unique<CpuRenderer>();
    } else {
        renderer = std::make_unique<GpuRenderer>(gpu::ContextOptions{o.device, gpu::validation_requested_by_environment()});
    }

    ProgressLine progress(o.quiet);
    auto start = std::chrono::steady_clock::now();
    FloatImage image = renderer->render(scene, [&](double f) {
        progress.update(output, f);
        return true;
    });
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_png(output, to_srgb8(image));

    const RenderSettings& r = scene.render;
    double rays = image.total_rays();
    progress.finish(fmt::format("{}: {}x{}, {} rays/pixel, {}: {:.3f} s, {:.2f} Mrays/s ({:.1f} M rays), peak RSS {} MiB",
                                output, r.width, r.height, r.samples * r.samples, renderer->description(), seconds,
                                rays / seconds / 1e6, rays / 1e6, peak_rss_mib()));
    renderer.reset();  // tear down Vulkan before counting validation messages
    if (std::uint32_t n = gpu::validation_message_count()) {
        std::fprintf(stderr, "lancer: error: %u Vulkan validation message(s)\n", n);
        return 1;
    }
    return 0;
}

}  // namespace lancer

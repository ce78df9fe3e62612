// `lancer render`: scene file -> PNG.
#include <chrono>
#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "cli/render_options.hpp"
#include "gpu/context.hpp"

namespace lancer {
namespace {

struct RenderCommand {
    RenderOptions options;
    bool list_devices = false;

    int run() const {
        if (list_devices) return lancer::list_devices();
        Scene scene = load_scene_with_overrides(options);
        std::string output = output_path(options);
        check_output_writable(output);
        std::unique_ptr<Renderer> renderer = make_renderer(options);

        ProgressLine progress(options.quiet);
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
        renderer.reset();  // tear Vulkan down before counting validation messages
        if (std::uint32_t n = gpu::validation_message_count()) {
            std::fprintf(stderr, "lancer: error: %u Vulkan validation message(s)\n", n);
            return 1;
        }
        return 0;
    }
};

}  // namespace

Subcommand add_render_command(CLI::App& parent) {
    auto state = std::make_shared<RenderCommand>();
    CLI::App* cmd = parent.add_subcommand("render", "Render a scene file to a PNG");
    add_render_options(*cmd, state->options);
    cmd->add_flag("--list-devices", state->list_devices, "List the Vulkan devices and exit");
    return {cmd, [state] { return state->run(); }};
}

int list_devices() {
    auto devices = gpu::Context::list_devices();
    if (devices.empty()) std::printf("no Vulkan devices\n");
    for (const auto& d : devices) std::printf("%u: %s (%s, %s)\n", d.index, d.name.c_str(), d.type.c_str(), d.driver.c_str());
    return 0;
}

}  // namespace lancer

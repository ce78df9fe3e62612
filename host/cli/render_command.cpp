// `lancer render`: scene file -> PNG, or an animated scene -> frames (and a video).
#include <cstdio>
#include <memory>
#include <utility>

#include <fmt/format.h>

#include "cli/animation_runner.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "app/frame_pattern.hpp"
#include "app/render_options.hpp"
#include "cli/still_render.hpp"
#include "gpu/vulkan/context.hpp"

namespace lancer {
namespace {

// One note per implicit surface: whether lancer took its function for a polynomial, and of
// which degree (the CPU reference then solves it by companion matrix; otherwise by interval
// Newton), so that a user can tell which path a surface takes.
void report_implicit_surfaces(const Scene& scene) {
    for_each_object_and_leaf(scene.objects, [](const Object& o) {
        const auto* implicit = std::get_if<ImplicitObject>(&o.shape);
        if (!implicit) return;
        int degree = implicit->surface->degree();
        std::string what = degree > 0 ? fmt::format("a polynomial of degree {}", degree) : "not a polynomial";
        std::fprintf(stderr, "%s:%d:%d: note: implicit surface: %s\n", o.where.file.c_str(), o.where.line,
                     o.where.column, what.c_str());
    });
}

struct RenderCommand {
    RenderOptions options;
    AnimationOptions animation;
    bool list_devices = false;

    int run() const {
        if (list_devices) return lancer::list_devices();
        if (options.scene.empty()) throw UserError("render: a scene file is required (see lancer render --help)");
        RendererStart start(options);
        Scene scene = [&] {
            PhaseLine phase(options.quiet, "reading " + options.scene);
            return load_scene_with_overrides(options);
        }();
        if (!options.quiet) report_implicit_surfaces(scene);
        if (scene.animation || animation.requested()) return run_animation(options, animation, scene, start);
        std::string output = output_path(options);
        if (has_frame_field(output))
            throw UserError("-o " + output + ": a frame number pattern, but " + options.scene + " has no [animation] table");
        return render_still(options, std::move(scene), output, start);
    }
};

}  // namespace

Subcommand add_render_command(CLI::App& parent) {
    auto state = std::make_shared<RenderCommand>();
    CLI::App* cmd = parent.add_subcommand("render", "Render a scene file to a PNG, or an animated scene to frames");
    add_render_options(*cmd, state->options);
    add_animation_options(*cmd, state->animation);
    cmd->add_flag("--list-devices", state->list_devices, "List the Vulkan devices and exit");
    // `lancer render --list-devices` needs no scene; run() asks for one otherwise.
    cmd->get_option("scene")->required(false);
    return {cmd, [state] { return state->run(); }};
}

int list_devices() {
    auto devices = gpu::Context::list_devices();
    if (devices.empty()) std::printf("no Vulkan devices\n");
    for (const auto& d : devices) std::printf("%u: %s (%s, %s)\n", d.index, d.name.c_str(), d.type.c_str(), d.driver.c_str());
    return 0;
}

}  // namespace lancer

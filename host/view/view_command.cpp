// `lancer view`: the command line of the interactive viewer (view/viewer.hpp does the work).
#include <memory>

#include "view/view_command.hpp"
#include "app/option_checks.hpp"
#include "scene/animation.hpp"
#include "view/viewer.hpp"

namespace lancer {

Subcommand add_view_command(CLI::App& parent) {
    auto state = std::make_shared<view::ViewerOptions>();
    CLI::App* cmd = parent.add_subcommand(
        "view", "Open a window on a scene: move the camera with the keys and the mouse (h lists them), "
                "record sequences, save PNGs; shaders and the scene reload when they change");
    add_render_options(*cmd, state->render);
    cmd->get_option("--output")
        ->description("PNG that p saves: a name (overwritten), or a pattern such as shot_%03d.png (the first unused "
                      "number; default NAME-view-%03d.png)");
    cmd->get_option("--shaders")
        ->description("Shader directory to compile and watch (default: ./shaders if present, else the built-in shaders)");
    cmd->add_option("--frame", state->frame, "Frame of an animated scene to view (default 0)")->transform(decimal_integer());
    cmd->add_option("--dump-frame", state->dump_frame,
                    "Debugging and tests: write the window's pixels to this PNG after each finished refinement")
        ->check(png_file_name());
    cmd->add_option("--record-frames", state->record_frames, "Frames of the sequences f and l record (default 120)")
        ->transform(decimal_integer())
        ->check(CLI::Range(1, kMaxFrames));
    return {cmd, [state] { return view::run_viewer(*state); }};
}

}  // namespace lancer

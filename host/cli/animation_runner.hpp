#pragma once
// `lancer render` for an animated scene: which frames, where they go, resuming, the video.
#include <string>

#include <CLI/CLI.hpp>

#include "app/render_options.hpp"
#include "app/renderer_start.hpp"

namespace lancer {

struct AnimationOptions {
    std::string frames;  // --frames A-B or N (0-based, inclusive); empty: all
    bool force = false;  // render frames whose files exist already
    std::string video;   // --video FILE (.mp4, .webm, .gif)
    bool requested() const { return !frames.empty() || !video.empty(); }
};

void add_animation_options(CLI::App& cmd, AnimationOptions& o);

// Renders the frames of `scene` (loaded, with the command line's overrides) to the -o pattern,
// skipping finished ones unless --force, then makes the video if asked. One renderer serves
// every frame (from `renderer_start`), so start-up is paid once. Returns the exit code.
int run_animation(const RenderOptions& options, const AnimationOptions& animation, const Scene& scene, RendererStart& renderer_start);

}  // namespace lancer

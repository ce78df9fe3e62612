#pragma once
// Options shared by the commands that render a scene (render, and later watch and view):
// the scene, the output, overrides of [render], and the backend choice.
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace lancer {

struct RenderOptions {
    std::string scene;
    std::string output;
    std::optional<int> width, height, samples, max_depth;
    std::optional<double> exposure;
    std::string tone;
    // Photon mapping: photons per pass (switches it on), passes, and a range of them (a farm's part).
    std::optional<int> photons, passes;
    std::string pass_range;
    std::optional<double> aa_threshold;
    std::optional<int> aa_depth;
    std::string aa_method;
    std::string backend = "gpu";
    std::string device;
    std::string shader_dir;  // compile the tracer from these sources at run time (development)
    bool quiet = false;
};

void add_render_options(CLI::App& cmd, RenderOptions& o);

// Loads the scene and applies the command line's overrides of its [render] table.
Scene load_scene_with_overrides(const RenderOptions& o);

// What an image file of this scene's render records: its tone mapping and which photon passes
// its pixels average (a part of a farm render).
ExrInfo image_info(const Scene& scene);

// The output path: -o, or the scene's name with .png in the current directory.
std::string output_path(const RenderOptions& o);

// Fails early, before minutes of rendering, when the PNG could not be written anyway.
void check_output_writable(const std::string& path);

std::unique_ptr<Renderer> make_renderer(const RenderOptions& o);

long peak_rss_mib();

}  // namespace lancer

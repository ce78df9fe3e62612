#pragma once
// Options shared by the commands that render a scene (render, and later watch and view):
// the scene, the output, overrides of [render], and the backend choice.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/renderer.hpp"
#include "scene/scene.hpp"
#include "scene/scene_values.hpp"

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

// Loads the scene (its expressions at `time`) and applies the command line's overrides of its
// [render] table.
Scene load_scene_with_overrides(const RenderOptions& o, SceneTime time = {});

// Frame k of the animated scene `loaded` (as load_scene_with_overrides read it), static: read
// again at the frame's clock where the file's numbers depend on it, then moved by its tracks.
Scene scene_for_frame(const RenderOptions& o, const Scene& loaded, int k);

// What an image file of this scene's render records: its tone mapping and which photon passes
// its pixels average (a part of a farm render).
ExrInfo image_info(const Scene& scene);

// What determines the pixels of a render, for the stamp of a farm's part (lancer combine refuses
// parts whose stamps differ): a hash of the scene file and every file it read (patch files,
// textures), as 16 hex digits, and the settings after the command line's overrides, one
// "name value" per line (version, backend, size, samples, depth, camera, photons).
std::string scene_files_hash(const Scene& scene);
std::string render_settings_text(const Scene& scene, const RenderOptions& o);

// The files a render of the scene reads: the scene file and its dependencies (an output must
// not be one of them).
std::vector<std::string> scene_inputs(const Scene& scene);

// The output path: -o, or the scene's name with .png in the current directory.
std::string output_path(const RenderOptions& o);

// Fails early, before minutes of rendering, when the PNG could not be written anyway.
void check_output_writable(const std::string& path);

std::unique_ptr<Renderer> make_renderer(const RenderOptions& o);

long peak_rss_mib();

}  // namespace lancer

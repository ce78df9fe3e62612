#pragma once
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace lancer {

struct RenderOptions {
    std::string scene;
    std::string output;
    std::optional<int> width, height, samples, max_depth;
    std::string backend = "gpu";
    std::string device;
    bool list_devices = false;
    bool quiet = false;
};

CLI::App* add_render_command(CLI::App& app, RenderOptions& options);
int run_render(const RenderOptions& options);
int list_devices();

}  // namespace lancer

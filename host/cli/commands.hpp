#pragma once
// lancer's subcommands. Each registers its options on the parent app (bound to state the
// returned action owns) and returns what to run when it was the one given.
#include <functional>
#include <vector>

#include <CLI/CLI.hpp>

namespace lancer {

struct Subcommand {
    CLI::App* app;
    std::function<int()> run;
};

Subcommand add_render_command(CLI::App& parent);
Subcommand add_watch_command(CLI::App& parent);
Subcommand add_diff_command(CLI::App& parent);
Subcommand add_combine_command(CLI::App& parent);
Subcommand add_view_command(CLI::App& parent);  // host/view/view_command.cpp

int list_devices();

}  // namespace lancer

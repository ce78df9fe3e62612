#pragma once
// lancer's command-line subcommands (`lancer view` is host/view/view_command.hpp).
#include "app/subcommand.hpp"

namespace lancer {

Subcommand add_render_command(CLI::App& parent);
Subcommand add_watch_command(CLI::App& parent);
Subcommand add_diff_command(CLI::App& parent);
Subcommand add_combine_command(CLI::App& parent);

int list_devices();

}  // namespace lancer

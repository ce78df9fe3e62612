#pragma once
// `lancer view`: the interactive viewer's subcommand.
#include "app/subcommand.hpp"

namespace lancer {

Subcommand add_view_command(CLI::App& parent);

}  // namespace lancer

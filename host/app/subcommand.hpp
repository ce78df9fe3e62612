#pragma once
// One of lancer's subcommands. Each registers its options on the parent app (bound to state the
// returned action owns) and returns what to run when it was the one given.
#include <functional>

#include <CLI/CLI.hpp>

namespace lancer {

struct Subcommand {
    CLI::App* app;
    std::function<int()> run;
};

}  // namespace lancer

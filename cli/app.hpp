// The orthoray command line as one CLI::App: every subcommand with its
// options, built the same way for the program (main.cpp) and for the man
// pages and completion script generated from it (docgen_main.cpp), so the
// documentation cannot drift from the parser.
#pragma once

#include "commands.hpp"

#include <vector>

namespace orthoray::cli {

struct Subcommand {
    CLI::App* app;
    Command run;
};

// Sets up `app` (description, --version, the one-line subcommand list of
// --help) and registers every subcommand, in the order --help lists them.
std::vector<Subcommand> build_cli(CLI::App& app);

} // namespace orthoray::cli

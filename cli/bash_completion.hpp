// A bash completion script written from the command line's own definitions
// (app.cpp): subcommands, their options, and the choices of options that
// take one of a fixed set of words.
#pragma once

#include <CLI/CLI.hpp>

#include <ostream>

namespace orthoray::cli {

void write_bash_completion(const CLI::App& app, std::ostream& out);

} // namespace orthoray::cli

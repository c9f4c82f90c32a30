// Man pages written from the command line's own definitions (app.cpp), so
// that they cannot drift from what the parser accepts: orthoray(1) and one
// page a subcommand, orthoray-solve(1), orthoray-puzzle-solve(1), ...
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace orthoray::cli {

// Writes NAME.1 into `dir` for `app` and every subcommand below it;
// returns the files written.
std::vector<std::filesystem::path>
write_man_pages(const CLI::App& app, const std::filesystem::path& dir, const std::string& version);

// The first clause of a description, on one line: what --help lists and a
// man page's NAME line says.
std::string summary(const std::string& description);

} // namespace orthoray::cli

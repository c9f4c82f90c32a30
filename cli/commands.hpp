// The orthoray subcommands. Each registers its options on the app and returns
// the function that runs it; main() maps exceptions to exit statuses.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace orthoray::cli {

// Exit statuses of the command-line contract.
enum Exit : int { yes = 0, no = 1, bad_input = 2, limit = 3, internal_error = 4 };

using Command = std::function<int()>;

Command add_solve(CLI::App& app);
Command add_verify(CLI::App& app);

} // namespace orthoray::cli

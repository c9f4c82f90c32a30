// For the commands that write their output only at the end (render, bounds,
// convert, generate), and for every command until it sets up its own
// handling (main() installs this first thing): SIGINT, SIGTERM and
// --timeout end the process at once, from the signal handler, with one line
// on stderr and exit status 3. Nothing is lost: there was nothing to report
// yet, and an output being written is a temporary file that the handler
// removes (OutputFile), so the target is untouched. `solve` instead polls
// (run_monitor.hpp), since a stopped solve still reports how far it got.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>

namespace orthoray::cli {

// Adds --timeout SECONDS to a command, the same option as solve's.
CLI::Option* add_timeout_option(CLI::App* cmd, double& seconds, const std::string& what);

// Installs the handlers, and with a timeout an interval timer, for the rest
// of the process.
void stop_at_once(std::optional<double> timeout_seconds);

// From here on SIGINT, SIGTERM and the timer are held back until the process
// ends, so they no longer stop it: called once the answer is decided, before
// the result is printed or the outputs are renamed into place. A stop then
// would cut the printing short or leave some outputs in place, with exit 3,
// where the promise is nothing written; the command finishes instead.
void stop_no_more();

} // namespace orthoray::cli

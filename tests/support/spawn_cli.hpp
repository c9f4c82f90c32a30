// Runs the orthoray binary in the background, for tests that signal it or
// need a shell around it (pipes, ulimit, /dev/full as stdout).
#pragma once

#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace orthoray::test {

// Starts orthoray with `args`, stdout and stderr to the given files.
pid_t spawn_cli(const std::vector<std::string>& args, const std::string& out,
                const std::string& err);

// Waits for `child`: its exit status, or -signal when a signal ended it.
int wait_for(pid_t child);

// Waits for `child` at most `seconds`; kills it (and returns nullopt) past
// that, so a program that ignores a signal fails its test, not hangs it.
std::optional<int> wait_at_most(pid_t child, double seconds);

// A test that signals a child must not signal it before it handles the
// signal: it would die of it (exit 143 or 130), whatever the code does.
// These poll /proc until `child` has a handler for `signal` (SigCgt in
// /proc/PID/status), or until it holds `path` open (a link in
// /proc/PID/fd), or until the pipe read through `reader` holds `bytes`
// bytes (FIONREAD): then it waits where the test means it to. A minute is
// a guard that turns a hang into a failure, not a measurement; false past
// it or when the child has ended.
bool wait_until_catching(pid_t child, int signal);
bool wait_until_open(pid_t child, const std::string& path);
bool wait_until_queued(pid_t child, int reader, int bytes);

struct ShellResult {
    int status = -1;
    std::string err;
};

// Runs `bash -c SCRIPT`, where $ORTHORAY is the binary; stderr is captured,
// stdout goes where the script sends it (the test's /dev/null by default).
ShellResult run_shell(const std::string& script);

} // namespace orthoray::test

// Runs the orthoray binary in the background, for tests that signal it or
// need a shell around it (pipes, ulimit, /dev/full as stdout).
#pragma once

#include <string>
#include <sys/types.h>
#include <vector>

namespace orthoray::test {

// Starts orthoray with `args`, stdout and stderr to the given files.
pid_t spawn_cli(const std::vector<std::string>& args, const std::string& out,
                const std::string& err);

// Waits for `child`: its exit status, or -signal when a signal ended it.
int wait_for(pid_t child);

struct ShellResult {
    int status = -1;
    std::string err;
};

// Runs `bash -c SCRIPT`, where $ORTHORAY is the binary; stderr is captured,
// stdout goes where the script sends it (the test's /dev/null by default).
ShellResult run_shell(const std::string& script);

} // namespace orthoray::test

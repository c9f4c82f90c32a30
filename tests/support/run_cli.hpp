// Runs the orthoray binary the way a user would and captures what it says.
#pragma once

#include <string>

namespace orthoray::test {

struct CliResult {
    int status = -1;
    std::string out, err;
};

// `args` is appended to the binary's path as is (quote what needs quoting);
// standard input is the file `input` (nothing to read by default).
CliResult run_cli(const std::string& args, const std::string& input = "/dev/null");

std::string source_path(const std::string& relative);

} // namespace orthoray::test

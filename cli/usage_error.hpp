// A problem with the command line itself (not with an input file): reported
// as `orthoray: ...` with exit status 2. Apart from commands.hpp so that
// output_file.cpp, which the Python module shares, needs nothing else.
#pragma once

#include <stdexcept>

namespace orthoray::cli {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace orthoray::cli

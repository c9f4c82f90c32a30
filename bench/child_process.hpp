// Measuring in a forked child, shared by the bench executables: the child
// builds its scene itself and runs the work, so the peak resident set size
// (ru_maxrss from wait4) is that of one scene and one engine, and runs do
// not pollute each other's memory. Bench-local.
#pragma once

#include <functional>
#include <string>

namespace orthoray::bench {

struct ChildOutput {
    std::string bytes;   // what `work` returned, through a pipe
    int status = 0;      // the child's wait status
    long max_rss_kb = 0; // its peak resident set size, KiB
};

// Runs `work` in a child process. `work` must catch its own exceptions (an
// escaping one ends the child with its bytes unsent).
ChildOutput run_in_child(const std::function<std::string()>& work);

} // namespace orthoray::bench

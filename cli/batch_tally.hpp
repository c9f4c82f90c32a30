// What `orthoray batch` has done: counts the progress line and the closing
// summary read, and the exit status they imply.
#pragma once

#include "batch_instance.hpp"

#include <atomic>
#include <chrono>
#include <cstddef>

namespace orthoray::cli {

struct Tally {
    std::atomic<std::size_t> done{0}, skipped{0}, yes{0}, no{0}, bad{0}, limited{0};
    // Of the skipped, those whose result in the file is bad input or a limit.
    std::atomic<std::size_t> skipped_failures{0};

    void count(Ending ending);
    // `batch: N/T done, R/s, ETA S, F failed`, redrawn in place on stderr.
    void draw_progress(std::size_t total, std::chrono::steady_clock::time_point begin) const;
    // The closing summary on stderr, and the exit status: 0 every instance
    // decided, 1 some was bad input or at a limit (in this run, or in the
    // result --resume kept), 3 interrupted first.
    int finish(std::size_t total, double seconds) const;
};

} // namespace orthoray::cli

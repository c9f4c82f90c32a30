// Paces the polls of a RunMonitor in a loop of steps whose cost is not
// known in advance (machine integers or GMP, few or many elements): the
// chunk of steps between polls doubles while a chunk takes under 5 ms and
// halves while it takes over 20 ms (from 1 to 2^24 steps), so a stop
// request is seen within a few tens of milliseconds (docs/limits.md).
#pragma once

#include <chrono>
#include <cstdint>

namespace orthoray::engine {

class PollPacer {
public:
    // Counts one step; true when the monitor is due to be polled.
    bool due() {
        if (++done_ < chunk_) return false;
        done_ = 0;
        const Clock::time_point now = Clock::now();
        const double seconds = std::chrono::duration<double>(now - begin_).count();
        if (seconds < 0.005 && chunk_ < (std::uint64_t{1} << 24)) chunk_ *= 2;
        if (seconds > 0.02 && chunk_ > 1) chunk_ /= 2;
        begin_ = now;
        return true;
    }

private:
    using Clock = std::chrono::steady_clock;
    // From 1: on 10^6-digit coordinates one step takes milliseconds.
    std::uint64_t chunk_ = 1, done_ = 0;
    Clock::time_point begin_ = Clock::now();
};

} // namespace orthoray::engine

// The tail of a cycle found by Brent's method, for engines whose step map
// may join two states into one (one-sided elements: docs/optics.md).
#pragma once

#include "engine/poll_pacer.hpp"
#include "orthoray/solve.hpp"

#include <cstdint>
#include <optional>

namespace orthoray::engine {

struct TailSearch {
    std::uint64_t mu = 0;       // the least i >= 1 with s_i = s_(i + lambda)
    std::optional<Limit> limit; // set when the monitor stopped the search
};

// mu of docs/optics.md, by walking s_i and s_(i + lambda) side by side from
// i = 1 (the second pass of Brent's method): O(1) states. `behind` starts
// as s_1 and ends as s_mu, the state the cycle starts at; `step(walker)`
// moves a walker on by one reflection. The cycle is known, so no walker
// escapes or stops, and there are fewer than 2 (mu + lambda) steps.
// `monitor`, if any, is polled with `reflections` between chunks of about
// 10 ms (PollPacer), as stepping polls it.
template <class Walker, class Step>
TailSearch search_tail(Walker& behind, std::uint64_t lambda, Step&& step, RunMonitor* monitor,
                       std::uint64_t reflections) {
    Walker ahead = behind;
    PollPacer pacer;
    TailSearch found;
    // After one pair of steps (or one step of `ahead` while it runs ahead):
    // false when the monitor asks to stop.
    auto go_on = [&] {
        if (!monitor || !pacer.due()) return true;
        found.limit = monitor->poll(reflections);
        return !found.limit;
    };
    for (std::uint64_t i = 0; i < lambda; ++i) {
        step(ahead);
        if (!go_on()) return found;
    }
    found.mu = 1;
    while (!(behind == ahead)) {
        step(behind);
        step(ahead);
        ++found.mu;
        if (!go_on()) return found;
    }
    return found;
}

} // namespace orthoray::engine

// Polls a RunMonitor from inside the setup of a run on the lattice: scaling
// the scene, building a shooter (uniform grid, piece tables, cross-section
// grid, hierarchy) and the induction's interval exchange. Each is linear in
// the input, but on huge numbers one takes a few hundred milliseconds (a
// 10^6-digit product or quotient is some 20 to 50 ms), and a stop request
// must be honoured within 100 ms (docs/limits.md). The loops of a phase call
// the poll once per unit of work (an element, an event, a slot of the
// tables); it reads the clock and asks the monitor at most every few
// milliseconds, and when the monitor says stop it throws SetupStopped, which
// the engine catches where the run begins: the phase is abandoned as a
// whole, so no half-built structure is ever used, and no answer depends on
// when (or whether) the poll was made.
#pragma once

#include "orthoray/solve.hpp"

#include <chrono>
#include <cstdint>
#include <type_traits>

namespace orthoray::lattice {

// The limit a monitor gave in the middle of a setup phase.
struct SetupStopped {
    Limit limit;
};

class SetupPoll {
public:
    // Polls nothing: for setup outside a run (bounds, the pieces dump).
    SetupPoll() = default;
    // Polls `monitor` (may be null: nothing), reporting `reflections` done.
    // The clock is read every `stride` calls: 1 where a unit can take
    // milliseconds (GMP integers), more where a unit takes a microsecond or
    // less (machine integers), so that the clock (some 20 to 40 ns a read)
    // adds nothing measurable to the setup.
    SetupPoll(RunMonitor* monitor, std::uint64_t reflections, unsigned stride = 1)
        : monitor_(monitor), reflections_(reflections), stride_(stride) {}

    // One unit of setup work done: throws SetupStopped when the monitor,
    // asked once its interval has passed, says stop.
    // Only the count is inline: the loops stay as fast as without it.
    void operator()() const {
        if (monitor_ && ++calls_ >= stride_) [[unlikely]]
            check();
    }

    // A unit that is slow only on GMP integers (a shot through the grid,
    // many per element): counted there, free on machine integers, where
    // the enclosing loop's poll is often enough.
    template <class Int>
    void on_gmp() const {
        if constexpr (std::is_same_v<Int, Integer>) (*this)();
    }

private:
    [[gnu::noinline]] void check() const {
        calls_ = 0;
        const Clock::time_point now = Clock::now();
        if (now < next_) return;
        next_ = now + interval;
        if (const std::optional<Limit> limit = monitor_->poll(reflections_))
            throw SetupStopped{*limit};
    }

    using Clock = std::chrono::steady_clock;
    // Small beside the 100 ms a stop may take, large beside a monitor's cost.
    static constexpr std::chrono::milliseconds interval{2};
    RunMonitor* monitor_ = nullptr;
    std::uint64_t reflections_ = 0;
    unsigned stride_ = 1;
    // The builders take the poll as a const reference, so that they can
    // default it to one that polls nothing; only these counters move.
    mutable unsigned calls_ = 0;
    mutable Clock::time_point next_{};
};

} // namespace orthoray::lattice

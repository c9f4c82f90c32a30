// What `orthoray solve` watches while an engine runs: the --timeout deadline,
// SIGINT and SIGTERM, and the progress line on a terminal. --max-steps and
// --max-memory are enforced elsewhere (the engine's step cap, the address
// space limit), since they need no clock.
#pragma once

#include "orthoray/scene.hpp"
#include "orthoray/solve.hpp"

#include <chrono>
#include <cstdint>
#include <optional>

namespace orthoray::cli {

// From construction to destruction, SIGINT and SIGTERM ask the run to stop
// rather than kill the process (a second one kills it as usual); the previous
// handlers are restored afterwards.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;
    static bool requested();
};

// Limits the process's address space to its current size plus `megabytes`
// (and `reserved` bytes more, for what is about to be mapped outside the
// budget: batch's thread stacks), so allocations past it fail
// (std::bad_alloc, a limit) instead of swapping.
void limit_memory(std::uint64_t megabytes, std::uint64_t reserved = 0);

class SolveMonitor final : public RunMonitor {
public:
    using Clock = std::chrono::steady_clock;
    // `deadline`: when to stop with Limit::time. `progress`: draw the
    // progress line (only when stderr is a terminal). `unit`: what the
    // count polled means ("reflections", or "states" for a search).
    SolveMonitor(const Scene& scene, std::optional<Clock::time_point> deadline, bool progress,
                 const char* unit = "reflections");
    ~SolveMonitor() override;
    SolveMonitor(const SolveMonitor&) = delete;
    SolveMonitor& operator=(const SolveMonitor&) = delete;

    // `reflections`: for the illumination question, the branch states
    // expanded so far; the line then says so and shows resident memory.
    std::optional<Limit> poll(std::uint64_t reflections) override;
    // Erases the progress line, if one was drawn, before the answer is printed.
    void erase_progress();

private:
    const Scene& scene_;
    std::optional<Clock::time_point> deadline_;
    bool progress_;
    const char* unit_;
    Clock::time_point begin_, next_draw_;
    std::optional<Integer> state_bound_; // computed when the line is first drawn
    bool drawn_ = false;

    void draw(std::uint64_t reflections, Clock::time_point now);
};

} // namespace orthoray::cli

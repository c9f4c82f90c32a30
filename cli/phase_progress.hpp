// The progress line of the commands that have no count to report while
// they work (bounds, convert): which phase they are in and for how long,
//
//     orthoray bounds: reading huge.scene, 2.5 s
//
// or, for a search that counts its steps from other threads (the Lazor
// placement search), the count and its rate as `solve` shows them:
//
//     orthoray puzzle solve: searching level.bff, 1234567 nodes, 4.1e+05/s, 3.0 s
//
// drawn on stderr after the first second, refreshed four times a second by
// a thread of its own (the phases themselves, a read or a bound on huge
// numbers, poll nothing), and erased before the result is printed; only
// when stderr is a terminal, never on a file or a pipe (docs/limits.md).
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

namespace orthoray::cli {

// Whether a progress line is on the terminal now, for the handler that
// ends the process at once (stop_at_once.cpp) to erase it first.
bool progress_line_shown() noexcept;

class PhaseProgress {
public:
    // `command`: "bounds", "convert"; `enabled`: false for --quiet.
    PhaseProgress(std::string command, bool enabled);
    // Stops the thread and erases the line, also when an error unwinds.
    ~PhaseProgress();
    PhaseProgress(const PhaseProgress&) = delete;
    PhaseProgress& operator=(const PhaseProgress&) = delete;

    // What the command is doing now: "reading FILE", "writing FILE", ...
    void phase(std::string what);
    // Shows `counter` (read relaxed, as other threads add to it) after the
    // phase, with `unit` ("nodes") and its rate; until phase() is called
    // again with a new counter or none.
    void phase(std::string what, const std::atomic<std::uint64_t>* counter, std::string unit);
    // Stops the thread and erases the line; call before printing a result.
    void finish();

private:
    using Clock = std::chrono::steady_clock;
    void run();
    void draw();
    void erase();

    std::string command_;
    Clock::time_point begin_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::string phase_, unit_;
    const std::atomic<std::uint64_t>* counter_ = nullptr;
    bool stopping_ = false, drawn_ = false;
    std::thread thread_;
};

} // namespace orthoray::cli

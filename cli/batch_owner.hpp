// The process of `orthoray batch` that owns the results: the one process of a
// local batch, or rank 0 under MPI. It lists the instances, opens the
// results file, and starts its own threads deciding instances at once; the
// MPI coordinator hands the others out from the same counter.
#pragma once

#include "batch_inputs.hpp"
#include "batch_instance.hpp"
#include "batch_results.hpp"
#include "batch_tally.hpp"
#include "batch_threads.hpp"
#include "run_monitor.hpp"

#include <atomic>
#include <chrono>
#include <memory>

namespace orthoray::cli {

class BatchOwner {
public:
    BatchOwner(const BatchArgs& args, unsigned jobs);

    const InstanceList instances;
    std::unique_ptr<ResultsLog> log;
    Tally tally;
    std::atomic<std::size_t> next{0}; // the next instance not handed out
    const bool progress;              // draw the progress line (stderr is a terminal)

    // Appends an outcome's line and counts it; thread-safe.
    void record(const Outcome& outcome);
    void draw_progress() const { tally.draw_progress(instances.size(), begin_); }
    // Waits for the threads (drawing the progress line), closes the file,
    // sorts it when every instance has its line, and prints the summary:
    // the batch's exit status.
    int finish();

private:
    const InterruptGuard interrupts_;
    const InstanceDecider decider_;
    const DoneCheck done_;
    const std::chrono::steady_clock::time_point begin_;
    BatchThreads threads_;
};

} // namespace orthoray::cli

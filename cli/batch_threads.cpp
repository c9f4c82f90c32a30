#include "batch_threads.hpp"

#include "run_monitor.hpp"
#include "usage_error.hpp"

#include <string>
#include <system_error>

namespace orthoray::cli {

BatchThreads::BatchThreads(unsigned jobs, const InstanceList& instances,
                           std::atomic<std::size_t>& next, const InstanceDecider& decider,
                           const DoneCheck& done, Record record)
    : instances_(instances), next_(next), decider_(decider), done_(done),
      record_(std::move(record)), running_(jobs) {
    try {
        for (unsigned j = 0; j < jobs; ++j) threads_.emplace_back([this] { work(); });
    } catch (const std::system_error& e) {
        // The destructor does not run for a constructor that throws: stop
        // and join the threads started, or their std::thread would
        // terminate the process.
        failed_ = true;
        for (std::thread& t : threads_) t.join();
        throw UsageError("found --jobs " + std::to_string(jobs) + ", expected at most " +
                         std::to_string(threads_.size()) +
                         " (no more threads could start: " + e.code().message() + ")");
    }
}

BatchThreads::~BatchThreads() {
    failed_ = true;
    for (std::thread& t : threads_)
        if (t.joinable()) t.join();
}

void BatchThreads::work() {
    try {
        while (!InterruptGuard::requested() && !failed_) {
            const std::size_t i = next_++;
            if (i >= instances_.size()) break;
            const Outcome outcome = decider_.decide(instances_.name(i), done_);
            if (outcome.ending == Ending::interrupted) break;
            record_(outcome);
        }
    } catch (...) {
        const std::lock_guard lock(mutex_);
        if (!failure_) failure_ = std::current_exception();
        failed_ = true;
    }
    const std::lock_guard lock(mutex_);
    --running_;
    finished_.notify_all();
}

bool BatchThreads::finished_within(std::chrono::milliseconds wait) {
    std::unique_lock lock(mutex_);
    return finished_.wait_for(lock, wait, [this] { return running_ == 0; });
}

void BatchThreads::join() {
    for (std::thread& t : threads_) t.join();
    threads_.clear();
    if (failure_) std::rethrow_exception(failure_);
}

} // namespace orthoray::cli

// The threads of one `orthoray batch` process: each takes the next instance
// index from a shared counter as it finishes one, so cheap and expensive
// instances balance themselves (instances differ in cost by orders of
// magnitude; a fixed split would leave threads idle).
#pragma once

#include "batch_inputs.hpp"
#include "batch_instance.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace orthoray::cli {

class BatchThreads {
public:
    // What a thread does with an outcome: append its line, count it. Called
    // from the threads; it must be thread-safe.
    using Record = std::function<void(const Outcome&)>;

    // Starts `jobs` threads deciding instances.name(next++) until the list is
    // exhausted, a signal comes, or a thread fails (a write error).
    BatchThreads(unsigned jobs, const InstanceList& instances, std::atomic<std::size_t>& next,
                 const InstanceDecider& decider, const DoneCheck& done, Record record);
    ~BatchThreads();
    BatchThreads(const BatchThreads&) = delete;
    BatchThreads& operator=(const BatchThreads&) = delete;

    // Whether every thread has ended, waiting at most `wait` for it.
    bool finished_within(std::chrono::milliseconds wait);
    // Joins the threads and rethrows the first failure.
    void join();

private:
    void work();

    const InstanceList& instances_;
    std::atomic<std::size_t>& next_;
    const InstanceDecider& decider_;
    const DoneCheck& done_;
    Record record_;
    std::atomic<bool> failed_{false};
    std::exception_ptr failure_;
    std::mutex mutex_;
    std::condition_variable finished_;
    unsigned running_;
    std::vector<std::thread> threads_;
};

} // namespace orthoray::cli

// For searches that only read a stop flag (the Lazor placement search):
// a thread that sets the flag once a deadline passes or SIGINT/SIGTERM
// arrives (under an InterruptGuard, run_monitor.hpp). Used by
// `puzzle solve` and by `batch` for each level it decides.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

namespace orthoray::cli {

class StopWatcher {
public:
    using Clock = std::chrono::steady_clock;
    // Checks every few milliseconds until destroyed (then it wakes at once).
    StopWatcher(std::atomic<bool>& stop, std::optional<Clock::time_point> deadline);
    ~StopWatcher();
    StopWatcher(const StopWatcher&) = delete;
    StopWatcher& operator=(const StopWatcher&) = delete;
    // Whether it was a signal, not the deadline, that set the flag.
    bool interrupted() const { return interrupted_.load(); }

private:
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_ = false;
    std::atomic<bool> interrupted_{false};
    std::thread thread_;
};

} // namespace orthoray::cli

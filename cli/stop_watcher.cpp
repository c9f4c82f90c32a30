#include "stop_watcher.hpp"

#include "run_monitor.hpp"

namespace orthoray::cli {

StopWatcher::StopWatcher(std::atomic<bool>& stop, std::optional<Clock::time_point> deadline)
    : thread_([this, &stop, deadline] {
          std::unique_lock lock(mutex_);
          while (!done_) {
              if (InterruptGuard::requested()) {
                  interrupted_ = true;
                  stop = true;
              } else if (deadline && Clock::now() >= *deadline) {
                  stop = true;
              }
              wake_.wait_for(lock, std::chrono::milliseconds(5));
          }
      }) {}

StopWatcher::~StopWatcher() {
    {
        const std::lock_guard lock(mutex_);
        done_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

} // namespace orthoray::cli

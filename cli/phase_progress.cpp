#include "phase_progress.hpp"

#include <atomic>
#include <cstdio>
#include <unistd.h>

namespace orthoray::cli {
namespace {

// Read by a signal handler: lock-free.
std::atomic<bool> line_shown{false};
static_assert(std::atomic<bool>::is_always_lock_free);

} // namespace

bool progress_line_shown() noexcept {
    return line_shown.load(std::memory_order_relaxed);
}

PhaseProgress::PhaseProgress(std::string command, bool enabled)
    : command_(std::move(command)), begin_(Clock::now()) {
    if (enabled && isatty(STDERR_FILENO)) thread_ = std::thread([this] { run(); });
}

PhaseProgress::~PhaseProgress() {
    finish();
}

void PhaseProgress::phase(std::string what) {
    phase(std::move(what), nullptr, "");
}

void PhaseProgress::phase(std::string what, const std::atomic<std::uint64_t>* counter,
                          std::string unit) {
    const std::lock_guard lock(mutex_);
    phase_ = std::move(what);
    counter_ = counter;
    unit_ = std::move(unit);
}

void PhaseProgress::finish() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
    erase();
}

void PhaseProgress::run() {
    std::unique_lock lock(mutex_);
    // Short runs never show the line.
    auto next = begin_ + std::chrono::seconds(1);
    while (!wake_.wait_until(lock, next, [this] { return stopping_; })) {
        draw();
        next = Clock::now() + std::chrono::milliseconds(250);
    }
}

// With mutex_ held (from run).
void PhaseProgress::draw() {
    // Display only: floating point never reaches an answer.
    const double seconds = std::chrono::duration<double>(Clock::now() - begin_).count();
    if (counter_) {
        const std::uint64_t count = counter_->load(std::memory_order_relaxed);
        std::fprintf(stderr, "\r\033[Korthoray %s: %s, %llu %s, %.3g/s, %.1f s", command_.c_str(),
                     phase_.c_str(), static_cast<unsigned long long>(count), unit_.c_str(),
                     static_cast<double>(count) / seconds, seconds);
    } else {
        std::fprintf(stderr, "\r\033[Korthoray %s: %s, %.1f s", command_.c_str(), phase_.c_str(),
                     seconds);
    }
    std::fflush(stderr);
    drawn_ = true;
    line_shown.store(true, std::memory_order_relaxed);
}

// After the thread has ended.
void PhaseProgress::erase() {
    if (!drawn_) return;
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    drawn_ = false;
    line_shown.store(false, std::memory_order_relaxed);
}

} // namespace orthoray::cli

#include "run_monitor.hpp"

#include "orthoray/bounds.hpp"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <unistd.h>

namespace orthoray::cli {
namespace {

// Set by the signal handler, read between chunks of work; a lock-free atomic
// is safe to store to from a handler.
std::atomic<bool> interrupt_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

struct sigaction previous_int, previous_term;

extern "C" void request_interrupt(int) {
    interrupt_requested.store(true, std::memory_order_relaxed);
}

void install(int signal, struct sigaction& previous) {
    struct sigaction action {};
    action.sa_handler = request_interrupt;
    sigemptyset(&action.sa_mask);
    // One signal asks politely; the handler then reverts to the default, so
    // a second one ends the process at once.
    action.sa_flags = SA_RESETHAND;
    sigaction(signal, &action, &previous);
}

} // namespace

InterruptGuard::InterruptGuard() {
    interrupt_requested = false;
    install(SIGINT, previous_int);
    install(SIGTERM, previous_term);
}

InterruptGuard::~InterruptGuard() {
    sigaction(SIGINT, &previous_int, nullptr);
    sigaction(SIGTERM, &previous_term, nullptr);
}

bool InterruptGuard::requested() {
    return interrupt_requested.load(std::memory_order_relaxed);
}

void limit_memory(std::uint64_t megabytes, std::uint64_t reserved) {
    // /proc/self/statm: the first field is the address space in pages.
    std::uint64_t pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const std::uint64_t page = static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
    const std::uint64_t cap = pages * page + (megabytes << 20) + reserved;
    const rlimit limit{cap, cap};
    setrlimit(RLIMIT_AS, &limit);
}

SolveMonitor::SolveMonitor(const Scene& scene, std::optional<Clock::time_point> deadline,
                           bool progress, const char* unit)
    : scene_(scene), deadline_(deadline), progress_(progress && isatty(STDERR_FILENO)), unit_(unit),
      begin_(Clock::now()),
      // Short runs never show the line.
      next_draw_(begin_ + std::chrono::seconds(1)) {}

SolveMonitor::~SolveMonitor() {
    erase_progress();
}

std::optional<Limit> SolveMonitor::poll(std::uint64_t reflections) {
    if (InterruptGuard::requested()) return Limit::interrupt;
    const Clock::time_point now = Clock::now();
    if (deadline_ && now >= *deadline_) return Limit::time;
    if (progress_ && now >= next_draw_) {
        draw(reflections, now);
        next_draw_ = now + std::chrono::milliseconds(250);
    }
    return std::nullopt;
}

// Resident memory in megabytes (/proc/self/statm: size, then resident
// pages); display only.
static double resident_megabytes() {
    std::uint64_t size = 0, resident = 0;
    std::ifstream("/proc/self/statm") >> size >> resident;
    return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1048576.0;
}

// count / bound as a percentage with one decimal, rounded down, in exact
// integer arithmetic: permille = floor(1000 count / bound). A run that has
// begun but not reached a tenth of a percent says "<0.1%", not "0.0%".
static std::string percent_of(std::uint64_t count, const Integer& bound) {
    const Integer permille = Integer(static_cast<unsigned long>(count)) * 1000 / bound;
    if (permille == 0 && count > 0) return "<0.1%";
    const Integer whole = permille / 10, tenths = permille % 10;
    return whole.get_str() + "." + tenths.get_str() + "%";
}

void SolveMonitor::draw(std::uint64_t count, Clock::time_point now) {
    // Display only: floating point never reaches an answer.
    const double seconds = std::chrono::duration<double>(now - begin_).count();
    std::string line = std::to_string(count) + " " + unit_;
    char numbers[64];
    std::snprintf(numbers, sizeof numbers, ", %.3g/s, %.1f s", count / seconds, seconds);
    line += numbers;
    if (!scene_.single_trajectory()) {
        // What a long illumination search runs out of is memory: its
        // branch states stay stored (docs/optics.md).
        std::snprintf(numbers, sizeof numbers, ", %.0f MB resident", resident_megabytes());
        line += numbers;
    } else {
        if (!state_bound_) state_bound_ = compute_bounds(scene_, false).refined_states;
        if (*state_bound_ > 0) {
            const std::string bound = state_bound_->get_str();
            line += ", " + percent_of(count, *state_bound_) + " of the ";
            line += bound.size() <= 12 ? bound : "10^" + std::to_string(bound.size() - 1) + "+";
            line += " states bound";
        }
    }
    std::fprintf(stderr, "\r\033[K%s", line.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void SolveMonitor::erase_progress() {
    if (!drawn_) return;
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    drawn_ = false;
}

} // namespace orthoray::cli

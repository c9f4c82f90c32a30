#include "stop_at_once.hpp"

#include "option_checks.hpp"
#include "output_file.hpp"
#include "phase_progress.hpp"

#include <cmath>
#include <csignal>
#include <cstring>
#include <sys/time.h>
#include <unistd.h>

namespace orthoray::cli {
namespace {

// Only async-signal-safe calls: write, unlink (inside
// remove_unfinished_output), a lock-free atomic load and _exit.
extern "C" void stop_now(int signal) {
    const char* message = signal == SIGALRM ? "orthoray: stopped: --timeout reached\n"
                                            : "orthoray: stopped: interrupted\n";
    remove_unfinished_output();
    // The message replaces a progress line rather than trailing it.
    const char* erase = "\r\033[K";
    ssize_t ignored = 0;
    if (progress_line_shown()) ignored = ::write(STDERR_FILENO, erase, std::strlen(erase));
    ignored = ::write(STDERR_FILENO, message, std::strlen(message));
    (void)ignored;
    _exit(3);
}

} // namespace

CLI::Option* add_timeout_option(CLI::App* cmd, double& seconds, const std::string& what) {
    return cmd
        ->add_option("--timeout", seconds,
                     "stop " + what +
                         " after SECONDS (a decimal, counted from the start): "
                         "nothing is written, exit 3")
        ->check(timeout_seconds());
}

void stop_at_once(std::optional<double> timeout_seconds) {
    struct sigaction action {};
    action.sa_handler = stop_now;
    sigemptyset(&action.sa_mask);
    for (const int signal : {SIGINT, SIGTERM, SIGALRM}) sigaction(signal, &action, nullptr);
    if (!timeout_seconds) return;
    double whole = 0;
    const double fraction = std::modf(*timeout_seconds, &whole);
    itimerval timer{};
    timer.it_value.tv_sec = static_cast<time_t>(whole);
    timer.it_value.tv_usec = static_cast<suseconds_t>(fraction * 1e6);
    if (timer.it_value.tv_sec == 0 && timer.it_value.tv_usec == 0) timer.it_value.tv_usec = 1;
    setitimer(ITIMER_REAL, &timer, nullptr);
}

void stop_no_more() {
    sigset_t held;
    sigemptyset(&held);
    for (const int signal : {SIGINT, SIGTERM, SIGALRM}) sigaddset(&held, signal);
    sigprocmask(SIG_BLOCK, &held, nullptr);
}

} // namespace orthoray::cli

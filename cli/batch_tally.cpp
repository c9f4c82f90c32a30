#include "batch_tally.hpp"

#include "commands.hpp"

#include <cstdio>

namespace orthoray::cli {

void Tally::count(Ending ending) {
    switch (ending) {
    case Ending::yes:
        ++yes;
        break;
    case Ending::no:
        ++no;
        break;
    case Ending::bad_input:
        ++bad;
        break;
    case Ending::limit:
        ++limited;
        break;
    case Ending::skipped:
        ++skipped;
        break;
    case Ending::skipped_failure:
        ++skipped;
        ++skipped_failures;
        break;
    case Ending::interrupted:
        return;
    }
    ++done;
}

void Tally::draw_progress(std::size_t total, std::chrono::steady_clock::time_point begin) const {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    const std::size_t finished = done, decided = finished - skipped;
    const double rate = elapsed > 0 ? static_cast<double>(decided) / elapsed : 0;
    char eta[32] = "?";
    if (rate > 0)
        std::snprintf(eta, sizeof eta, "%.0f s", static_cast<double>(total - finished) / rate);
    std::fprintf(stderr, "\r\033[Kbatch: %zu/%zu done, %.1f/s, ETA %s, %zu failed", finished, total,
                 rate, eta, bad + limited);
}

int Tally::finish(std::size_t total, double seconds) const {
    std::fprintf(stderr,
                 "batch: %zu of %zu instances in %.3f s: %zu yes, %zu no, %zu bad input, %zu at a "
                 "limit, %zu already in the results",
                 done.load(), total, seconds, yes.load(), no.load(), bad.load(), limited.load(),
                 skipped.load());
    if (skipped_failures > 0)
        std::fprintf(stderr, " (%zu of them bad input or at a limit)", skipped_failures.load());
    std::fputc('\n', stderr);
    if (done < total) {
        std::fprintf(stderr, "orthoray: stopped: interrupted; 'orthoray batch --resume -o FILE' "
                             "goes on where it stopped\n");
        return limit;
    }
    return bad + limited + skipped_failures > 0 ? Exit::no : Exit::yes;
}

} // namespace orthoray::cli

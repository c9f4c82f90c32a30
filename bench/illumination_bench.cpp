// illumination_bench: the space-bounded illumination search (docs/optics.md)
// against a naive baseline in the same run, on growing random splitter
// scenes in 2D and 3D: bench/scenes.hpp's random mirror boxes with every
// third inner mirror a splitter, and a target no branch reaches (the parity
// argument of random_box holds for every branch), so neither search stops
// early and both run to their caps.
//
// - new: solve() with max_steps = B branch states expanded; reports branch
//   states expanded per second, events stepped per second, the branch
//   states stored, the bytes it accounts for them (set, labels, queue:
//   Answer::stats.illumination.state_bytes) and the peak heap growth seen
//   by this program's allocation hooks, both per stored state.
// - naive: the search it replaced, Dijkstra over every state in a
//   std::map of exact rational states (and a std::priority_queue of them),
//   capped at the same number of events, so both step the same amount.
//
// Times are medians of --runs runs; memory is deterministic (one run).
// Floating point appears only in the printed figures. How to run it:
// bench/README.md.
#include "bench_util.hpp"
#include "scenes.hpp"

#include "engine/reference_step.hpp"
#include "orthoray/solve.hpp"

#include "parse_options.hpp"

#include <malloc.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <new>
#include <queue>
#include <string>
#include <tuple>

namespace {

// Live and peak heap bytes: every operator new and every GMP allocation.
std::size_t live_bytes = 0, peak_bytes = 0;

void note_alloc(void* p) {
    if (!p) return;
    live_bytes += malloc_usable_size(p);
    if (live_bytes > peak_bytes) peak_bytes = live_bytes;
}
void note_free(void* p) {
    if (p) live_bytes -= malloc_usable_size(p);
}

void* gmp_alloc(std::size_t n) {
    void* p = std::malloc(n);
    if (!p) std::abort();
    note_alloc(p);
    return p;
}
void* gmp_realloc(void* p, std::size_t, std::size_t n) {
    note_free(p);
    void* q = std::realloc(p, n);
    if (!q) std::abort();
    note_alloc(q);
    return q;
}
void gmp_free(void* p, std::size_t) {
    note_free(p);
    std::free(p);
}

// Out of line, so that GCC, inlining operator delete into the standard
// containers, does not take the replacement's free() for a mismatch.
[[gnu::noinline]] void release(void* p) noexcept {
    note_free(p);
    std::free(p);
}

} // namespace

void* operator new(std::size_t n) {
    void* p = std::malloc(n ? n : 1);
    if (!p) throw std::bad_alloc();
    note_alloc(p);
    return p;
}
void operator delete(void* p) noexcept {
    release(p);
}
void operator delete(void* p, std::size_t) noexcept {
    release(p);
}

namespace orthoray::bench {
namespace {

// The bytes the heap grew by at its peak while f ran.
template <class F>
std::size_t peak_growth(F&& f) {
    const std::size_t before = live_bytes;
    peak_bytes = live_bytes;
    f();
    return peak_bytes - before;
}

Scene splitter_box(int dim, std::int64_t n) {
    Scene s =
        random_box(dim, n, 12 + static_cast<std::uint64_t>(n) + static_cast<std::uint64_t>(dim));
    for (std::size_t i = static_cast<std::size_t>(2 * dim); i < s.elements.size(); i += 3)
        s.elements[i].kind = ElementKind::splitter;
    return s;
}

// The naive baseline: the search before docs/optics.md's branch states,
// every state in an exact std::map, expanded in (reflections, ray) order
// until `events` states are expanded. Returns the states stored.
std::size_t naive_search(const Scene& scene, std::uint64_t events) {
    using State = std::pair<Vector, Vector>;
    std::map<State, bool> settled;
    using Entry = std::tuple<std::uint64_t, std::size_t, State>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::size_t r = 0; r < scene.rays.size(); ++r) {
        State s{scene.rays[r].start, scene.rays[r].direction};
        settled.emplace(s, false);
        queue.emplace(0, r + 1, std::move(s));
    }
    std::uint64_t expanded = 0;
    while (!queue.empty() && expanded < events) {
        auto [k, ray, s] = queue.top();
        queue.pop();
        bool& done = settled[s];
        if (done) continue;
        done = true;
        ++expanded;
        const engine::ReferenceEvent e = engine::reference_step(scene, s.first, s.second);
        engine::reference_passes(scene, scene.target(), s.first, s.second, e);
        for (const engine::Outgoing& o : e.outgoing) {
            State next{e.point, o.direction};
            if (settled.emplace(next, false).first->second) continue;
            queue.emplace(k + o.reflection, ray, std::move(next));
        }
    }
    return settled.size();
}

std::string fixed(double x, int digits = 1) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", digits, x);
    return b;
}
std::string si(double x) {
    char b[64];
    if (x >= 1e6)
        std::snprintf(b, sizeof b, "%.3g M", x / 1e6);
    else if (x >= 1e3)
        std::snprintf(b, sizeof b, "%.3g k", x / 1e3);
    else
        std::snprintf(b, sizeof b, "%.3g", x);
    return b;
}

int run(int argc, char** argv) {
    int runs = 3;
    std::int64_t max_n = 10000;
    double work = 3e6; // elements x events per run
    std::string csv_path = "bench/results/illumination.csv";
    bool quick = false;
    CLI::App app{"illumination_bench: branch walks against the naive walk"};
    app.add_flag("--quick", quick, "1 run, n up to 1000, work 3e5 (given options still win)");
    CLI::Option* runs_option =
        app.add_option("--runs", runs, "timed runs per scene")->capture_default_str();
    CLI::Option* max_n_option =
        app.add_option("--max-n", max_n, "largest scene, in elements")->capture_default_str();
    CLI::Option* work_option =
        app.add_option("--work", work, "elements x events per run")->capture_default_str();
    app.add_option("--csv", csv_path, "where the rows go")->capture_default_str();
    orthoray::bench::parse_options(app, "illumination_bench", argc, argv);
    if (quick) {
        if (runs_option->count() == 0) runs = 1;
        if (max_n_option->count() == 0) max_n = 1000;
        if (work_option->count() == 0) work = 3e5;
    }
    mp_set_memory_functions(gmp_alloc, gmp_realloc, gmp_free);
    Table table({"scene", "elements", "branch states expanded", "events", "new: branch states/s",
                 "new: events/s", "naive: events/s", "new: states stored", "naive: states stored",
                 "new: bytes/state (accounted)", "new: bytes/state (heap peak)",
                 "naive: bytes/state (heap peak)", "heap peak naive / new"});
    Csv csv(csv_path);
    csv.row({"dim", "elements", "expanded", "events", "new_seconds", "naive_seconds", "new_states",
             "naive_states", "new_accounted_bytes", "new_heap_peak", "naive_heap_peak"});
    for (int dim : {2, 3})
        for (std::int64_t n = 100; n <= max_n; n *= 10) {
            const Scene scene = splitter_box(dim, n);
            SolveOptions options;
            options.max_steps = static_cast<std::uint64_t>(work / static_cast<double>(n) / 2);
            Answer answer;
            const std::size_t new_peak = peak_growth([&] { answer = solve(scene, options); });
            if (answer.reason != Reason::limit) {
                std::fprintf(stderr, "illumination_bench: the search ended before its cap\n");
                return 1;
            }
            const std::uint64_t events = answer.stats.illumination.events;
            std::size_t naive_states = 0;
            const std::size_t naive_peak =
                peak_growth([&] { naive_states = naive_search(scene, events); });
            std::vector<double> new_times, naive_times;
            for (int r = 0; r < runs; ++r) {
                auto begin = std::chrono::steady_clock::now();
                solve(scene, options);
                new_times.push_back(seconds_since(begin));
                begin = std::chrono::steady_clock::now();
                naive_search(scene, events);
                naive_times.push_back(seconds_since(begin));
            }
            const double tn = median(new_times), tb = median(naive_times);
            const double stored = static_cast<double>(answer.states.get_ui());
            const std::uint64_t expanded = answer.stats.illumination.expanded;
            const std::string name = "random " + std::to_string(dim) + "D n=" + std::to_string(n);
            table.add({name, std::to_string(scene.elements.size()), std::to_string(expanded),
                       std::to_string(events), si(static_cast<double>(expanded) / tn),
                       si(static_cast<double>(events) / tn), si(static_cast<double>(events) / tb),
                       std::to_string(answer.states.get_ui()), std::to_string(naive_states),
                       fixed(static_cast<double>(answer.stats.illumination.state_bytes) / stored),
                       fixed(static_cast<double>(new_peak) / stored),
                       fixed(static_cast<double>(naive_peak) / static_cast<double>(naive_states)),
                       fixed(static_cast<double>(naive_peak) / static_cast<double>(new_peak))});
            csv.row({std::to_string(dim), std::to_string(scene.elements.size()),
                     std::to_string(expanded), std::to_string(events), fixed(tn, 6), fixed(tb, 6),
                     std::to_string(answer.states.get_ui()), std::to_string(naive_states),
                     std::to_string(answer.stats.illumination.state_bytes),
                     std::to_string(new_peak), std::to_string(naive_peak)});
            std::fprintf(stderr, "%s done\n", name.c_str());
        }
    table.print();
    return 0;
}

} // namespace
} // namespace orthoray::bench

int main(int argc, char** argv) {
    return orthoray::bench::run(argc, argv);
}

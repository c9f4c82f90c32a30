// illumination_bench: the space-bounded illumination search (docs/optics.md)
// with its two steppers, and a naive baseline, in the same run, on growing
// random splitter scenes in 2D and 3D: bench/scenes.hpp's random mirror
// boxes with every third inner mirror a splitter, and a target no branch
// reaches (the parity argument of random_box holds for every branch), so no
// search stops early and each runs to its cap; then the same 2D boxes with
// every fourth inner mirror on a diagonal, the target outside the box.
//
// - lattice: solve()'s search, stepping on the rays' lattices with the
//   uniform grid (engine/lattice_stepper.hpp), or on 2D scenes with
//   diagonals on their octagonal lattices with the hierarchy, capped at
//   --events events;
//   reports events and branch states expanded per second, the branch states
//   stored, the bytes it accounts for them (Answer::stats.illumination.
//   state_bytes) and the peak heap growth seen by this program's allocation
//   hooks per stored state (the grids are built before and reported apart,
//   as bytes per element).
// - scan: the same search stepping with the reference scan (O(n) an event),
//   the stepper it had before, capped at --work / n events.
// - naive: the search before branch states, Dijkstra over every state in a
//   plain std::unordered_map of full exact rational states, expanding as
//   many states as the scan stepped events, so that both do the same
//   scanning.
//
// Times are medians of --runs runs; memory is deterministic (one run).
// Floating point appears only in the printed figures. How to run it:
// bench/README.md.
#include "bench_util.hpp"
#include "scenes.hpp"

#include "engine/illumination.hpp"
#include "engine/lattice_stepper.hpp"
#include "engine/reference_step.hpp"
#include "orthoray/solve.hpp"

#include "parse_options.hpp"

#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <new>
#include <optional>
#include <queue>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

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

// splitter_box in 2D with every fourth inner element laid on a diagonal
// from its low end, rising and falling by turns, as long as the mirror where
// the box leaves room (docs/octagonal.md): the lattice stepper then steps
// on octagonal lattices with its hierarchy. The parity argument that keeps
// splitter_box's target dark fails across diagonals, but the box is closed:
// the target moves outside it.
Scene diagonal_splitter_box(std::int64_t n) {
    const Scene axis = splitter_box(2, n);
    Scene s = axis;
    s.elements.clear();
    const Rational side(box_side);
    for (std::size_t i = 0; i < axis.elements.size(); ++i) {
        const Element& e = axis.elements[i];
        const bool rising = i % 8 == 1, falling = i % 8 == 5;
        // The walls (the first four) stay.
        Rational length = e.hi[0] - e.lo[0] + e.hi[1] - e.lo[1];
        const Rational room_x = side - 1 - e.lo[0];
        const Rational room_y = rising ? Rational(side - 1 - e.lo[1]) : Rational(e.lo[1] - 1);
        length = std::min({length, room_x, room_y});
        if (i < 4 || !(rising || falling) || length <= 0) {
            s.elements.push_back(e);
            continue;
        }
        s.add_diagonal(e.kind, e.lo[0], e.lo[1], e.lo[0] + length,
                       rising ? Rational(e.lo[1] + length) : Rational(e.lo[1] - length));
    }
    s.targets = {Vector{-1, -1, 0}};
    return s;
}

using State = std::pair<Vector, Vector>;

// A hash of a full exact state: its rationals' limbs, mixed (FNV-1a steps,
// then a multiplicative spread per number).
struct StateHash {
    std::size_t operator()(const State& s) const {
        std::uint64_t h = 0;
        auto mix = [&h](mpz_srcptr z) {
            std::uint64_t x = 1469598103934665603u ^ (mpz_sgn(z) < 0 ? 1u : 0u);
            for (std::size_t i = 0; i < mpz_size(z); ++i)
                x = (x ^ static_cast<std::uint64_t>(mpz_getlimbn(z, static_cast<mp_size_t>(i)))) *
                    1099511628211u;
            h = (h ^ x) * 0x9e3779b97f4a7c15u;
        };
        for (const Vector* v : {&s.first, &s.second})
            for (const Rational& q : *v) {
                mix(q.get_num_mpz_t());
                mix(q.get_den_mpz_t());
            }
        return static_cast<std::size_t>(h);
    }
};

// The naive baseline: the search before docs/optics.md's branch states,
// every state in a hash table of full exact states, expanded in
// (reflections, ray) order until `events` states are expanded. Returns the
// states stored.
std::size_t naive_search(const Scene& scene, std::uint64_t events) {
    std::unordered_map<State, bool, StateHash> settled;
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

// One timed search with `stepper`, capped at `events` events.
Answer search(const Scene& scene, const engine::EventStepper& stepper, std::uint64_t events) {
    SolveOptions options;
    options.max_steps = events;
    return engine::solve_illumination(scene, options, stepper);
}

int run(int argc, char** argv) {
    int runs = 3;
    std::int64_t max_n = 100000;
    double events = 2e5; // events a run of the lattice search
    double work = 3e6;   // elements x events a run of the scan and the naive search
    std::string csv_path = "bench/results/illumination.csv";
    bool quick = false;
    CLI::App app{"illumination_bench: the branch search's steppers against the naive search"};
    app.add_flag("--quick", quick,
                 "1 run, n up to 1000, events 2e4, work 3e5 (given options still win)");
    CLI::Option* runs_option =
        app.add_option("--runs", runs, "timed runs per scene")->capture_default_str();
    CLI::Option* max_n_option =
        app.add_option("--max-n", max_n, "largest scene, in elements")->capture_default_str();
    CLI::Option* events_option =
        app.add_option("--events", events, "events a run of the lattice search")
            ->capture_default_str();
    CLI::Option* work_option =
        app.add_option("--work", work, "elements x events a run of the scan and the naive search")
            ->capture_default_str();
    app.add_option("--csv", csv_path, "where the rows go")->capture_default_str();
    orthoray::bench::parse_options(app, "illumination_bench", argc, argv);
    if (quick) {
        if (runs_option->count() == 0) runs = 1;
        if (max_n_option->count() == 0) max_n = 1000;
        if (events_option->count() == 0) events = 2e4;
        if (work_option->count() == 0) work = 3e5;
    }
    mp_set_memory_functions(gmp_alloc, gmp_realloc, gmp_free);
    Table table({"scene", "elements", "lattice: events", "lattice: events/s",
                 "lattice: branch states/s", "scan: events/s", "naive: events/s", "lattice / scan",
                 "states stored", "bytes/state (accounted)", "bytes/state (heap peak)",
                 "naive: bytes/state (heap peak)", "shooters: bytes/element", "shooters: build s"});
    Csv csv(csv_path);
    csv.row({"dim", "diagonals", "elements", "lattice_events", "lattice_expanded",
             "lattice_seconds", "scan_events", "scan_seconds", "naive_seconds", "states",
             "accounted_bytes", "heap_peak", "naive_states", "naive_heap_peak", "grid_bytes",
             "grid_seconds"});
    // 2D and 3D axis-parallel scenes (the uniform grid), then 2D scenes
    // with diagonals (the octagonal lattices' hierarchy).
    for (const auto& [dim, diagonals] : {std::pair{2, false}, {3, false}, {2, true}})
        for (std::int64_t n = 100; n <= max_n; n *= 10) {
            const Scene scene = diagonals ? diagonal_splitter_box(n) : splitter_box(dim, n);
            const auto fast_events = static_cast<std::uint64_t>(events);
            const auto scan_events = std::max<std::uint64_t>(
                1, static_cast<std::uint64_t>(work / static_cast<double>(n)));
            std::optional<engine::LatticeStepper> lattice;
            auto begin = std::chrono::steady_clock::now();
            const std::size_t grid_bytes = peak_growth([&] { lattice.emplace(scene); });
            const double grid_seconds = seconds_since(begin);
            const engine::ReferenceStepper scan(scene);
            Answer answer;
            const std::size_t peak =
                peak_growth([&] { answer = search(scene, *lattice, fast_events); });
            if (answer.reason != Reason::limit) {
                std::fprintf(stderr, "illumination_bench: the search ended before its cap\n");
                return 1;
            }
            std::size_t naive_states = 0;
            const std::size_t naive_peak =
                peak_growth([&] { naive_states = naive_search(scene, scan_events); });
            std::vector<double> fast_times, scan_times, naive_times;
            for (int r = 0; r < runs; ++r) {
                begin = std::chrono::steady_clock::now();
                search(scene, *lattice, fast_events);
                fast_times.push_back(seconds_since(begin));
                begin = std::chrono::steady_clock::now();
                search(scene, scan, scan_events);
                scan_times.push_back(seconds_since(begin));
                begin = std::chrono::steady_clock::now();
                naive_search(scene, scan_events);
                naive_times.push_back(seconds_since(begin));
            }
            const double tf = median(fast_times), ts = median(scan_times), tb = median(naive_times);
            const double fast_rate = static_cast<double>(fast_events) / tf;
            const double scan_rate = static_cast<double>(scan_events) / ts;
            const double stored = static_cast<double>(answer.states.get_ui());
            const std::uint64_t expanded = answer.stats.illumination.expanded;
            const double elements = static_cast<double>(scene.elements.size());
            const std::string name = "random " + std::to_string(dim) + "D" +
                                     (diagonals ? " diagonals" : "") + " n=" + std::to_string(n);
            table.add({name, std::to_string(scene.elements.size()), std::to_string(fast_events),
                       si(fast_rate), si(static_cast<double>(expanded) / tf), si(scan_rate),
                       si(static_cast<double>(scan_events) / tb), fixed(fast_rate / scan_rate),
                       std::to_string(answer.states.get_ui()),
                       fixed(static_cast<double>(answer.stats.illumination.state_bytes) / stored),
                       fixed(static_cast<double>(peak) / stored),
                       fixed(static_cast<double>(naive_peak) / static_cast<double>(naive_states)),
                       fixed(static_cast<double>(grid_bytes) / elements), fixed(grid_seconds, 3)});
            csv.row({std::to_string(dim), diagonals ? "1" : "0",
                     std::to_string(scene.elements.size()), std::to_string(fast_events),
                     std::to_string(expanded), fixed(tf, 6), std::to_string(scan_events),
                     fixed(ts, 6), fixed(tb, 6), std::to_string(answer.states.get_ui()),
                     std::to_string(answer.stats.illumination.state_bytes), std::to_string(peak),
                     std::to_string(naive_states), std::to_string(naive_peak),
                     std::to_string(grid_bytes), fixed(grid_seconds, 6)});
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

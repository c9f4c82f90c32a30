// The Embree baseline (bench/README.md, "The Embree baseline"): Embree's
// reflections per second next to the exact engine's and the float grid's on
// the random benchmark scenes, in the same run, and how far Embree's path
// follows the exact one. Compiled with the Embree parts only when CMake
// found Embree (ORTHORAY_BENCH_EMBREE); otherwise the part says so.
#include "orthoray_bench.hpp"

#include <cstdio>
#include <functional>
#include <string>

#ifdef ORTHORAY_BENCH_EMBREE
#include "bench_util.hpp"
#include "child_process.hpp"
#include "embree_tracer.hpp"
#include "measurement.hpp"
#include "scenes.hpp"

#include "orthoray/solve.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>
#endif

namespace orthoray::bench {

#ifndef ORTHORAY_BENCH_EMBREE
int embree_baseline(const Options&) {
    std::printf("## Embree baseline\n\nSkipped: CMake did not find Embree 3 when this program "
                "was built (install libembree-dev and reconfigure).\n\n");
    return 0;
}
int embree_smoke(const std::function<void(const std::string&)>&) {
    return 0;
}
#else
namespace {

ChildResult run_embree(const Scene& scene, std::uint64_t steps, bool robust) {
    const auto begin = std::chrono::steady_clock::now();
    const EmbreeTracer tracer(scene, robust);
    const EmbreeAnswer a = tracer.trace(steps);
    ChildResult r;
    r.wall = seconds_since(begin);
    r.reason = a.reason;
    r.reflections = a.reflections;
    r.performed = a.reason == Reason::cycle ? a.reflections + 1 : a.reflections;
    r.setup = a.setup_seconds;
    return r;
}

// The peak resident memory (KiB) of a child from the moment its scene is
// built to the end of `trace`. The kernel's high-water mark is reset after
// the scene (clear_refs 5), so the scene's live data counts but not its
// transient building peak, which in the process's ru_maxrss hides a tracer
// smaller than that transient (Embree's, at every size here). Reflections
// do not add memory, so a short trace measures the same peak.
long tracing_peak_kb(const std::function<Scene()>& make,
                     const std::function<void(const Scene&)>& trace) {
    const ChildOutput out = run_in_child([&] {
        const Scene scene = make();
        std::ofstream("/proc/self/clear_refs") << "5";
        trace(scene);
        std::ifstream status("/proc/self/status");
        for (std::string line; std::getline(status, line);)
            if (line.rfind("VmHWM:", 0) == 0) return line.substr(6); // "   1234 kB"
        return std::string();
    });
    return std::atol(out.bytes.c_str());
}

// Net reflections per second of each run (setup excluded), its setup, and the
// last answer.
struct Rates {
    std::vector<double> rate;
    std::vector<double> setup;  // seconds before the first reflection
    std::vector<double> rss_mb; // each run's process: the scene and the tracer
    ChildResult last;
    bool ok = true;
    void add(const Measured& m) {
        if (!m.result.ok) {
            ok = false;
            std::fprintf(stderr, "[embree] a run failed: %s\n", m.result.error);
            return;
        }
        last = m.result;
        rss_mb.push_back(static_cast<double>(m.max_rss_kb) / 1024);
        setup.push_back(m.result.setup);
        const double net = m.result.wall - m.result.setup;
        rate.push_back(net > 0 ? static_cast<double>(m.result.performed) / net : 0);
    }
};

std::string outcome(const ChildResult& r) {
    return std::string(to_string(r.reason)) + " " + power_of_ten(r.reflections);
}

// Where Embree's path first leaves the exact one (the reflection index:
// 1 is the first reflection), or 0 if it never did within the compared
// reflections.
struct Divergence {
    std::uint64_t first_off = 0;   // hit point off by more than 1e-9 x the scene's size
    std::uint64_t first_loose = 0; // off by more than 1e-6 x the size
    std::uint64_t first_wrong = 0; // hit an element the exact point is not on
    std::uint64_t compared = 0;    // reflections compared
    bool leak = false, false_hit = false;
};

Divergence diverge(const Scene& scene, const std::vector<Vector>& exact, bool robust) {
    double size = 1;
    for (const Element& e : scene.elements)
        for (int j = 0; j < scene.dim; ++j)
            size = std::max({size, std::fabs(e.lo[j].get_d()), std::fabs(e.hi[j].get_d())});
    Divergence d;
    const std::uint64_t cap = exact.size() - 1; // exact[0] is the start
    const EmbreeTracer tracer(scene, robust);
    const EmbreeAnswer a = tracer.trace(cap, [&](const double* p, std::uint32_t element) {
        const std::uint64_t i = ++d.compared;
        if (d.first_wrong) return true; // the paths are unrelated now; only leaks count
        const Vector& x = exact[i];
        double off = 0;
        for (int j = 0; j < scene.dim; ++j) off = std::max(off, std::fabs(p[j] - x[j].get_d()));
        if (!d.first_off && off > 1e-9 * size) d.first_off = i;
        if (!d.first_loose && off > 1e-6 * size) d.first_loose = i;
        if (!scene.elements[element].contains(x)) d.first_wrong = i;
        return true;
    });
    // The scenes are closed mirror boxes whose target is never reached (scenes.hpp).
    d.leak = a.reason == Reason::escape;
    d.false_hit = a.reason == Reason::hit;
    if (d.leak || d.false_hit) d.first_wrong = d.first_wrong ? d.first_wrong : a.reflections + 1;
    return d;
}

std::string index_text(const std::vector<std::uint64_t>& firsts, std::uint64_t cap) {
    std::vector<double> v;
    std::uint64_t never = 0;
    for (std::uint64_t f : firsts) {
        if (f == 0) ++never;
        v.push_back(f == 0 ? static_cast<double>(cap) + 1 : static_cast<double>(f));
    }
    const double m = median(v);
    std::string s = fixed(m, m == std::floor(m) ? 0 : 1);
    if (never) s += " (" + std::to_string(never) + " never)";
    return s;
}

} // namespace

int embree_baseline(const Options& o) {
    const std::uint64_t steps = o.steps;
    std::printf("## Embree baseline (INEXACT, bench/embree_tracer.hpp)\n\n");
    std::printf("Embree %d.%d.%d, one thread, single-precision quads (2D: segments extruded "
                "along z). %s reflections a run, median of %d runs, each in its own process, "
                "exact / float / Embree / Embree robust alternating.\n\n",
                RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH,
                power_of_ten(steps).c_str(), o.runs);
    Table speed({"scene", "exact refl/s", "float refl/s", "Embree refl/s", "Embree robust refl/s",
                 "exact / Embree", "exact / Embree robust", "exact / float", "float / Embree",
                 "Embree setup s (robust)", "exact setup s", "exact setup / Embree setup",
                 "peak RSS MB exact; Embree", "outcome exact; float; Embree; robust"});
    const std::uint64_t memory_steps = 1000; // reflections of the memory runs
    Table memory({"scene", "scene MB", "exact MB", "Embree MB", "Embree robust MB",
                  "exact / Embree", "exact - scene MB", "Embree - scene MB"});
    std::vector<std::int64_t> sizes = {100, 1000, 10'000};
    if (!o.quick) sizes.push_back(100'000);
    int failures = 0;
    for (int dim : {2, 3})
        for (std::int64_t n : sizes) {
            if (o.dim && dim != o.dim) continue;
            const std::uint64_t seed = 1000 * static_cast<std::uint64_t>(dim) + 1;
            auto make = [&] { return random_box(dim, n, seed); };
            std::fprintf(stderr, "[embree] random %dD n = %lld\n", dim, static_cast<long long>(n));
            Rates exact, flt, fast, robust;
            for (int run = 0; run < o.runs; ++run) {
                exact.add(in_child([&] { return run_exact(make(), steps, Engine::lattice); }));
                flt.add(in_child([&] { return run_float(make(), steps); }));
                fast.add(in_child([&] { return run_embree(make(), steps, false); }));
                robust.add(in_child([&] { return run_embree(make(), steps, true); }));
            }
            for (const Rates* r : {&exact, &flt, &fast, &robust}) failures += r->ok ? 0 : 1;
            const double e = median(exact.rate), f = median(flt.rate), b = median(fast.rate),
                         br = median(robust.rate);
            auto ratio = [](double x, double y) { return sig3(y > 0 ? x / y : 0); };
            speed.add({"random " + std::to_string(dim) +
                           "D n=" + power_of_ten(static_cast<std::uint64_t>(n)),
                       rate_text(e), rate_text(f), rate_text(b), rate_text(br), ratio(e, b),
                       ratio(e, br), ratio(e, f), ratio(f, b),
                       sig3(median(fast.setup)) + " (" + sig3(median(robust.setup)) + ")",
                       sig3(median(exact.setup)), ratio(median(exact.setup), median(fast.setup)),
                       fixed(median(exact.rss_mb), 1) + "; " + fixed(median(fast.rss_mb), 1),
                       outcome(exact.last) + "; " + outcome(flt.last) + "; " + outcome(fast.last) +
                           "; " + outcome(robust.last)});
            const long scene_kb = tracing_peak_kb(make, [](const Scene&) {});
            const long exact_kb = tracing_peak_kb(
                make, [&](const Scene& s) { run_exact(s, memory_steps, Engine::lattice); });
            const long fast_kb =
                tracing_peak_kb(make, [&](const Scene& s) { run_embree(s, memory_steps, false); });
            const long robust_kb =
                tracing_peak_kb(make, [&](const Scene& s) { run_embree(s, memory_steps, true); });
            memory.add({"random " + std::to_string(dim) +
                            "D n=" + power_of_ten(static_cast<std::uint64_t>(n)),
                        mb(scene_kb), mb(exact_kb), mb(fast_kb), mb(robust_kb),
                        ratio(static_cast<double>(exact_kb), static_cast<double>(fast_kb)),
                        mb(exact_kb - scene_kb), mb(fast_kb - scene_kb)});
        }
    std::printf("### Reflections per second (median, setup excluded)\n\n");
    speed.print();
    std::printf("### Peak memory while tracing\n\n");
    std::printf("Peak resident memory of a process from the moment its scene (GMP rationals) "
                "is built: \"scene\" builds it only; the others then trace %s reflections "
                "(memory does not grow with them).\n\n",
                power_of_ten(memory_steps).c_str());
    memory.print();

    // Divergence: the exact path (the lattice engine's reflection points,
    // recorded) against Embree's, reflection by reflection, on several seeds.
    const std::uint64_t cap = o.quick ? 10'000 : 100'000;
    const int seeds = o.quick ? 3 : 10;
    std::printf("### Where Embree's path leaves the exact one\n\n");
    std::printf(
        "%d seeds a row, up to %s reflections compared. Median reflection index "
        "(1 = the first) where Embree's hit point is first more than 1e-9 x the scene's "
        "size from the exact one (and 1e-6), and where it first hits an element the exact point "
        "is not on (\"never\": not within the cap, counted as the cap + 1). Leaks: "
        "Embree escapes the closed box; false hits: it reports the target, which is "
        "never reached (leaks and false hits count over all the compared reflections, also "
        "after the paths have parted).\n\n",
        seeds, power_of_ten(cap).c_str());
    Table div({"scene", "flags", "first > 1e-9 off", "first > 1e-6 off", "first wrong element",
               "leaks", "false hits"});
    for (int dim : {2, 3})
        for (std::int64_t n : sizes) {
            if (n > 10'000 || (o.dim && dim != o.dim)) continue;
            std::vector<std::uint64_t> off[2], loose[2], wrong[2];
            int leaks[2] = {}, false_hits[2] = {};
            for (int s = 1; s <= seeds; ++s) {
                const Scene scene =
                    random_box(dim, n, 1000 * static_cast<std::uint64_t>(dim) + 100 + s);
                PathRecorder path;
                SolveOptions options;
                options.engine = Engine::lattice;
                options.max_steps = cap;
                options.path = &path;
                solve(scene, options);
                for (int r = 0; r < 2; ++r) {
                    const Divergence d = diverge(scene, path.points, r == 1);
                    off[r].push_back(d.first_off);
                    loose[r].push_back(d.first_loose);
                    wrong[r].push_back(d.first_wrong);
                    leaks[r] += d.leak;
                    false_hits[r] += d.false_hit;
                }
            }
            for (int r = 0; r < 2; ++r)
                div.add({"random " + std::to_string(dim) +
                             "D n=" + power_of_ten(static_cast<std::uint64_t>(n)),
                         r ? "robust" : "default", index_text(off[r], cap),
                         index_text(loose[r], cap), index_text(wrong[r], cap),
                         std::to_string(leaks[r]) + " / " + std::to_string(seeds),
                         std::to_string(false_hits[r]) + " / " + std::to_string(seeds)});
        }
    div.print();
    return failures;
}

int embree_smoke(const std::function<void(const std::string&)>& fail) {
    int compared = 0;
    for (int dim : {2, 3}) {
        const Scene scene = random_box(dim, 1000, 1000 * static_cast<std::uint64_t>(dim) + 1);
        PathRecorder path;
        SolveOptions options;
        options.engine = Engine::lattice;
        options.max_steps = 20'000;
        options.path = &path;
        solve(scene, options);
        for (bool robust : {false, true}) {
            const Divergence d = diverge(scene, path.points, robust);
            ++compared;
            const std::string what = "Embree" + std::string(robust ? " robust" : "") +
                                     " on random " + std::to_string(dim) + "D n=1000: ";
            if (d.compared != 20'000 || d.leak || d.false_hit)
                fail(what + "stopped after " + std::to_string(d.compared) +
                     " of 20000 reflections");
            if (d.first_wrong != 0 && d.first_wrong <= 10)
                fail(what + "left the exact path at reflection " + std::to_string(d.first_wrong));
        }
    }
    return compared;
}
#endif

} // namespace orthoray::bench

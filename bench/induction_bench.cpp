// induction_bench: time to the answer against orbit length for the
// induction engine (docs/induction.md) and the lattice simulation, on 2D
// families whose orbits grow: box corners (coprime (2^k + 1) x 2^k and
// consecutive Fibonacci sides), hallways, and random mirror mazes in a closed
// box with coordinates up to 10^18. The simulation is linear in the
// reflections, so it only runs up to a cap; the induction always runs. Where
// both run their answers must be identical (the bench aborts otherwise), and
// where a family knows its answer in closed form both must match it.
//
// Writes one CSV row per instance and engine (bench/plot_induction.gp draws
// it) and a markdown table on stdout. How to run it: bench/README.md.
// Floating point appears only in the timings and the printed ratios.
#include "bench_util.hpp"
#include "scenes.hpp"

#include "orthoray/allocator_policy.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/solve.hpp"

#include <unistd.h>

#include "parse_options.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace orthoray::bench {
namespace {

struct Options {
    bool quick = false;
    int runs = 5;
    Integer sim_cap = 300'000'000; // the simulation runs when reflections <= this
    std::string csv = "bench/results/induction.csv";
    // Only random mirrors in [0, 10^18]^2, this many (seed 1), when given:
    // the build-heavy sizes of issue 17 (10^4, 10^5) without the families.
    std::vector<std::int64_t> mirrors;
};

Options parse(int argc, char** argv) {
    Options o;
    std::string sim_cap;
    CLI::App app{"induction_bench: time to the answer against orbit length, induction against "
                 "the lattice simulation"};
    app.add_flag("--quick", o.quick, "small instances, 1 run, cap 10^7: a seconds-long smoke run");
    CLI::Option* runs =
        app.add_option("--runs", o.runs,
                       "timed solve() calls per instance and engine (default 5; a simulation "
                       "slower than 2 s runs once)")
            ->check(CLI::Range(1, 1000000));
    CLI::Option* cap =
        app.add_option("--sim-cap", sim_cap, "simulate only when reflections <= N (default 3e8)");
    app.add_option("--mirrors", o.mirrors,
                   "only random-N scenes in [0, 10^18]^2, seed 1, for each N given")
        ->check(CLI::Range(std::int64_t{1}, std::int64_t{10'000'000}));
    app.add_option("--csv", o.csv, "where the rows go (\"\" for none)")->capture_default_str();
    parse_options(app, "induction_bench", argc, argv);
    if (!sim_cap.empty()) {
        // Accept 3e8 as well as 300000000.
        const std::size_t e = sim_cap.find_first_of("eE");
        o.sim_cap = Integer(sim_cap.substr(0, e));
        if (e != std::string::npos)
            for (int j = std::stoi(sim_cap.substr(e + 1)); j > 0; --j) o.sim_cap *= 10;
    }
    if (o.quick) {
        if (runs->count() == 0) o.runs = 1;
        if (cap->count() == 0) o.sim_cap = 10'000'000;
    }
    return o;
}

// log base b of a positive integer, from its top 53 bits and its bit length.
double log_of(const Integer& x, double base) {
    if (x <= 0) return 0;
    long exponent = 0;
    const double mantissa = mpz_get_d_2exp(&exponent, x.get_mpz_t());
    return (std::log(mantissa) + static_cast<double>(exponent) * std::log(2.0)) / std::log(base);
}

std::string format(const char* pattern, double x) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, pattern, x);
    return buffer;
}

// Reflections for the table: exact below 10^7, else 1.23e29.
std::string short_count(const Integer& x) {
    if (x < 10'000'000) return x.get_str();
    const double l = log_of(x, 10);
    const double e = std::floor(l);
    return format("%.2f", std::pow(10.0, l - e)) + "e" + std::to_string(static_cast<int>(e));
}

struct Instance {
    std::string family; // coprime-box, fibonacci-box, hallway, random-100, random-1000
    std::string param;  // what grows: k, n, L, or range and seed
    std::function<GeneratedScene()> build;
};

Integer fibonacci(unsigned n) {
    Integer f;
    mpz_fib_ui(f.get_mpz_t(), n);
    return f;
}

Integer power(unsigned base, unsigned exponent) {
    Integer p;
    mpz_ui_pow_ui(p.get_mpz_t(), base, exponent);
    return p;
}

// Random mirrors in the closed box [0, 10^j]^2 (bench/scenes.hpp's
// random_box: the library's `random` family stops at 2^40), the target on
// the other lattice parity class than the start, so never reached: the
// answer is a cycle and the reflections are its period.
Instance random_instance(std::int64_t mirrors, unsigned j, std::uint64_t seed) {
    return {"random-" + std::to_string(mirrors),
            "range=10^" + std::to_string(j) + " seed=" + std::to_string(seed), [mirrors, j, seed] {
                GeneratedScene g;
                g.scene = random_box(2, mirrors, seed, power(10, j).get_si());
                g.notes.push_back("bench random_box: " + std::to_string(mirrors) +
                                  " mirrors in [0, 10^" + std::to_string(j) + "]^2, seed " +
                                  std::to_string(seed));
                return g;
            }};
}

std::vector<Instance> instances(bool quick, const std::vector<std::int64_t>& only_mirrors) {
    std::vector<Instance> out;
    if (!only_mirrors.empty()) {
        for (std::int64_t mirrors : only_mirrors) out.push_back(random_instance(mirrors, 18, 1));
        return out;
    }
    // (2^k + 1) x 2^k from the corner: 2^(k+1) - 1 reflections to the corner.
    const std::vector<unsigned> box_k =
        quick ? std::vector<unsigned>{4, 8, 12, 30}
              : std::vector<unsigned>{6,  8,  10, 12, 14, 16, 18, 20, 22, 24, 26,
                                      27, 30, 36, 42, 50, 60, 70, 80, 90, 99};
    for (unsigned k : box_k)
        out.push_back({"coprime-box", "k=" + std::to_string(k),
                       [k] { return generate_coprime_box(k, BoxFamily::Target::reached); }});
    // F(n+1) x F(n): the continued fraction of the side ratio is all ones,
    // the slowest one for Euclid, and F(n+2) - 2 reflections to the corner.
    const std::vector<unsigned> fib_n =
        quick ? std::vector<unsigned>{10, 20, 40}
              : std::vector<unsigned>{10, 14, 18, 22, 26, 30,  34,  38,  40,
                                      41, 50, 60, 70, 80, 100, 120, 140, 145};
    for (unsigned n : fib_n)
        out.push_back({"fibonacci-box", "n=" + std::to_string(n), [n] {
                           BoxFamily f;
                           f.sides = {fibonacci(n + 1), fibonacci(n)};
                           return generate_box(f);
                       }});
    // Two mirrors of length L, slope (L - 1) / (2L): floor(L / 2) reflections.
    const std::vector<unsigned> hall_j =
        quick ? std::vector<unsigned>{2, 4, 12}
              : std::vector<unsigned>{2, 3, 4, 5, 6, 7, 8, 10, 12, 15, 18, 21, 24, 27, 30};
    for (unsigned j : hall_j)
        out.push_back({"hallway", "L=10^" + std::to_string(j), [j] {
                           const Integer length = power(10, j);
                           return generate_hallway(Rational(length),
                                                   Rational(length - 1, 2 * length));
                       }});
    const std::vector<unsigned> range_j =
        quick ? std::vector<unsigned>{3, 6} : std::vector<unsigned>{3, 4, 5, 6, 9, 12, 15, 18};
    const std::vector<std::int64_t> mirror_counts =
        quick ? std::vector<std::int64_t>{100} : std::vector<std::int64_t>{100, 1000};
    const std::uint64_t seeds = quick ? 1 : 3;
    for (std::int64_t mirrors : mirror_counts)
        for (unsigned j : range_j)
            for (std::uint64_t seed = 1; seed <= seeds; ++seed)
                out.push_back(random_instance(mirrors, j, seed));
    return out;
}

struct Timed {
    Answer answer;            // of the last run
    double seconds;           // median wall time of solve()
    double induction_seconds; // median of Answer::induction.seconds
    int runs;
};

// Fresh solve() calls on the same scene; one only when the first is slow.
Timed time_solve(const Scene& scene, Engine engine, int runs) {
    SolveOptions options;
    options.engine = engine;
    std::vector<double> wall, induction;
    Answer answer;
    for (int r = 0; r < runs; ++r) {
        const auto begin = std::chrono::steady_clock::now();
        answer = solve(scene, options);
        wall.push_back(seconds_since(begin));
        induction.push_back(answer.stats.induction.seconds);
        if (r == 0 && wall.back() > 2.0) break;
    }
    return {answer, median(wall), median(induction), static_cast<int>(wall.size())};
}

std::string outcome(const Answer& a) {
    return std::string(to_string(a.reason)) + " " + a.reflections.get_str();
}

// A wrong answer is the finding that matters most: say everything and stop,
// leaving the scene next to the CSV to reproduce it with the CLI.
[[noreturn]] void disagree(const Instance& instance, const GeneratedScene& g,
                           const std::string& what, const std::string& expected,
                           const std::string& got) {
    const std::string path = "induction-mismatch.scene";
    std::ofstream(path) << write_generated(g, {"induction_bench: " + what});
    std::fprintf(stderr,
                 "\ninduction_bench: WRONG ANSWER on %s %s: %s\n  expected %s\n  got      %s\n"
                 "  scene written to %s\n",
                 instance.family.c_str(), instance.param.c_str(), what.c_str(), expected.c_str(),
                 got.c_str(), path.c_str());
    std::exit(1);
}

int run(const Options& o) {
    Csv csv(o.csv);
    csv.row({"family", "param", "elements", "engine", "reason", "reflections", "log10_reflections",
             "runs", "median_seconds", "pieces", "log2_states", "steps", "rounds", "k_log2_states",
             "steps_over_k_log2_states", "induction_seconds"});
    Table table({"family", "instance", "elements", "answer", "reflections", "induction s", "k",
                 "log2 N", "steps", "rounds", "steps / (k log2 N)", "simulation s",
                 "simulation / induction"});
    std::fprintf(stderr, "induction_bench: %d run(s), simulation up to %s reflections\n", o.runs,
                 o.sim_cap.get_str().c_str());
    for (const Instance& instance : instances(o.quick, o.mirrors)) {
        const GeneratedScene g = instance.build();
        const Scene& scene = g.scene;
        const std::string elements = std::to_string(scene.elements.size());

        const Timed ind = time_solve(scene, Engine::induction, o.runs);
        const Answer& a = ind.answer;
        if (!a.decided())
            disagree(instance, g, "induction did not decide", "an answer", outcome(a));
        if (g.expect && (g.expect->reason != a.reason || g.expect->reflections != a.reflections))
            disagree(instance, g, "induction against the closed form",
                     std::string(to_string(g.expect->reason)) + " " +
                         g.expect->reflections.get_str(),
                     outcome(a));
        const bool induced = a.engine == EngineUsed::induction;
        const double log2_n = log_of(a.stats.induction.states, 2);
        const double k_log_n = static_cast<double>(a.stats.induction.pieces) * log2_n;
        const double ratio =
            k_log_n > 0 ? static_cast<double>(a.stats.induction.steps) / k_log_n : 0;
        const std::string log10_r = format("%.4f", log_of(a.reflections, 10));
        const std::string reason = to_string(a.reason);
        csv.row({instance.family, instance.param, elements, "induction", reason,
                 a.reflections.get_str(), log10_r, std::to_string(ind.runs),
                 format("%.6g", ind.seconds),
                 induced ? std::to_string(a.stats.induction.pieces) : "",
                 induced ? format("%.4f", log2_n) : "",
                 induced ? std::to_string(a.stats.induction.steps) : "",
                 induced ? std::to_string(a.stats.induction.rounds) : "",
                 induced ? format("%.6g", k_log_n) : "", induced ? format("%.4f", ratio) : "",
                 induced ? format("%.6g", ind.induction_seconds) : ""});

        std::string sim_text = "-", speedup = "-";
        if (a.reflections <= o.sim_cap) {
            const Timed sim = time_solve(scene, Engine::lattice, o.runs);
            if (sim.answer.reason != a.reason || sim.answer.reflections != a.reflections)
                disagree(instance, g, "induction against simulation", outcome(sim.answer),
                         outcome(a));
            sim_text = format("%.3g", sim.seconds);
            speedup = ind.seconds > 0 ? format("%.3g", sim.seconds / ind.seconds) : "-";
            csv.row({instance.family, instance.param, elements, "lattice", reason,
                     a.reflections.get_str(), log10_r, std::to_string(sim.runs),
                     format("%.6g", sim.seconds), "", "", "", "", "", "", ""});
        } else {
            csv.row({instance.family, instance.param, elements, "lattice", "skipped",
                     a.reflections.get_str(), log10_r, "0", "", "", "", "", "", "", "", ""});
        }
        table.add({instance.family, instance.param, elements, reason, short_count(a.reflections),
                   format("%.3g", ind.seconds),
                   induced ? std::to_string(a.stats.induction.pieces) : "-",
                   induced ? format("%.1f", log2_n) : "-",
                   induced ? std::to_string(a.stats.induction.steps) : "-",
                   induced ? std::to_string(a.stats.induction.rounds) : "-",
                   induced ? format("%.2f", ratio) : "-", sim_text, speedup});
        std::fprintf(stderr, "  %-14s %-22s %-8s %-12s induction %.3g s (%s)  simulation %s s\n",
                     instance.family.c_str(), instance.param.c_str(), reason.c_str(),
                     short_count(a.reflections).c_str(), ind.seconds, to_string(a.engine),
                     sim_text.c_str());
    }
    std::printf("Median wall time of %d fresh solve() call(s) per instance and engine "
                "(a simulation over 2 s runs once); simulation only up to %s reflections.\n\n",
                o.runs, o.sim_cap.get_str().c_str());
    table.print();
    return 0;
}

} // namespace
} // namespace orthoray::bench

int main(int argc, char** argv) {
    orthoray::keep_freed_memory(); // as the command-line tool does
    try {
        return orthoray::bench::run(orthoray::bench::parse(argc, argv));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "induction_bench: %s\n", e.what());
        return 1;
    }
}

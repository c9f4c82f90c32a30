// orthoray_bench: the exact lattice engine against the naive exact reference
// tracer and a double-precision uniform-grid tracer (an inexact comparison
// baseline, bench/float_grid_tracer.hpp), on the same scenes in one run.
// How to run it and what every column means: bench/README.md. The figures of
// a full run are in bench/RESULTS.md.
//
// The parts: throughput.cpp (throughput, preprocessing, memory, the long
// run), disagreement.cpp (float against exact), embree_bench.cpp (the
// Embree baseline), smoke.cpp (the ctest
// check); every measurement runs in a forked child (child_process.hpp).
// This file parses the options (CLI11) and runs the parts asked for.
#include "orthoray_bench.hpp"
#include "parse_options.hpp"

#include "orthoray/allocator_policy.hpp"
#include "orthoray/build_info.hpp"

#include <CLI/CLI.hpp>

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <optional>
#include <string>

namespace orthoray::bench {
namespace {

// Accepts 1000000, 1e6 and 10^6; std::nullopt for anything else.
std::optional<std::uint64_t> parse_count(const std::string& text) {
    try {
        for (const char* sep : {"^", "e"}) {
            const std::size_t at = text.find(sep);
            if (at == std::string::npos) continue;
            const std::uint64_t base = std::stoull(text.substr(0, at));
            const int exponent = std::stoi(text.substr(at + 1));
            std::uint64_t value = sep[0] == '^' ? 1 : base;
            for (int i = 0; i < exponent; ++i) value *= sep[0] == '^' ? base : 10;
            return value;
        }
        std::size_t used = 0;
        const std::uint64_t value = std::stoull(text, &used);
        if (used == text.size()) return value;
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

// A count option: its text, checked by parse_count.
CLI::Option* add_count(CLI::App& app, const std::string& name, std::string& text,
                       const std::string& what) {
    return app.add_option(name, text, what)
        ->check(
            [](const std::string& value) -> std::string {
                return parse_count(value)
                           ? ""
                           : "found '" + value +
                                 "', expected a whole number such as 1000000, 1e6 or "
                                 "10^6";
            },
            "COUNT");
}

Options parse(int argc, char** argv) {
    Options o;
    CLI::App app{"orthoray_bench: the exact engine against the reference and float tracers "
                 "(see bench/README.md)",
                 "orthoray_bench"};
    std::string runs, steps, scenes, billion;
    app.add_flag("--quick", o.quick, "the whole program in about a minute");
    app.add_flag("--smoke", o.smoke, "the ctest bench_smoke check; prints one line");
    app.add_option("--mode", o.mode, "one part only (default all)")
        ->check(CLI::IsMember({"all", "throughput", "disagree", "billion", "embree", "memory"}));
    app.add_option("--csv", o.csv,
                   "also write the tables as CSV (FILE, FILE-billion.csv, "
                   "FILE-disagreement.csv)");
    add_count(app, "--runs", runs, "runs per measurement (default 5)");
    app.add_option("--dim", o.dim, "the embree part on 2D or 3D scenes only (default both)")
        ->check(CLI::IsMember({2, 3}));
    add_count(app, "--steps", steps, "reflections per exact and float run (default 3 * 10^7)");
    add_count(app, "--scenes", scenes, "disagreement scenes (default 3000)");
    add_count(app, "--billion", billion, "reflections of the long run (default 10^9)");
    app.add_option("--wrong-scene", o.wrong_scene,
                   "where to write the float-wrong instance (empty: nowhere)");
    app.add_option("--write-scenes", o.write_scenes,
                   "write the benchmark scenes as .scene files into DIR and stop");
    parse_options(app, "orthoray_bench", argc, argv);
    if (!runs.empty()) o.runs = static_cast<int>(std::max<std::uint64_t>(1, *parse_count(runs)));
    if (!steps.empty()) o.steps = *parse_count(steps);
    if (!scenes.empty()) o.scenes = *parse_count(scenes);
    if (!billion.empty()) o.billion = *parse_count(billion);
    if (o.quick && !o.steps) o.steps = 2'000'000;
    if (!o.steps) o.steps = 30'000'000;
    if (!o.scenes) o.scenes = o.quick ? 300 : 3000;
    if (!o.billion) o.billion = o.quick ? 100'000'000 : 1'000'000'000;
    if (!o.reference_work) o.reference_work = o.quick ? 1'000'000 : 10'000'000;
    if (o.quick && o.runs == 5) o.runs = 3;
    return o;
}

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return one + " " + five + " " + fifteen;
}

// The cores this process (and every contender it forks) may run on: all of
// them unless it was pinned (bench/against_embree.sh pins to one).
std::string cores_allowed() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) != 0) return "unknown cores";
    const long online = sysconf(_SC_NPROCESSORS_ONLN);
    if (CPU_COUNT(&set) == online) return "not pinned";
    std::string list;
    for (int c = 0; c < CPU_SETSIZE; ++c)
        if (CPU_ISSET(c, &set)) list += (list.empty() ? "" : ",") + std::to_string(c);
    return "pinned to CPU " + list;
}

void print_machine() {
    std::ifstream cpu("/proc/cpuinfo");
    std::string line, model;
    while (std::getline(cpu, line))
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    std::printf("Machine: %ld cores online, %s, %.1f GB memory; load average %s; %s.\n"
                "Built from commit %s.\n\n",
                sysconf(_SC_NPROCESSORS_ONLN), model.empty() ? "unknown CPU" : model.c_str(),
                static_cast<double>(pages) * static_cast<double>(page) / 1e9,
                load_average().c_str(), cores_allowed().c_str(), build_info().commit.c_str());
}

} // namespace
} // namespace orthoray::bench

int main(int argc, char** argv) {
    using namespace orthoray::bench;
    // As the command-line tool does: every contender (each run forks from
    // here) gets the same allocator policy.
    orthoray::keep_freed_memory();
    try {
        const Options o = parse(argc, argv);
        if (o.smoke) return smoke();
        if (!o.write_scenes.empty()) return write_scenes(o.write_scenes);
        std::printf("# orthoray_bench%s\n\n", o.quick ? " --quick" : "");
        print_machine();
        int failures = 0;
        const bool all = o.mode == "all";
        if (all || o.mode == "throughput") failures += throughput(o);
        if (all || o.mode == "billion") failures += billion(o);
        if (all || o.mode == "disagree") failures += disagreements(o);
        if (all || o.mode == "embree") failures += embree_baseline(o);
        if (all || o.mode == "memory") failures += memory_ladder(o);
        std::printf("Load average at the end: %s.\n", load_average().c_str());
        return failures == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "orthoray_bench: %s\n", e.what());
        return 4;
    }
}

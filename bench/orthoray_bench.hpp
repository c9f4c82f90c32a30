// orthoray_bench's parts (bench/README.md): the options its main parses,
// and one function a part, each printing its markdown tables and returning
// its failure count.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#ifndef ORTHORAY_BENCH_DIR
#define ORTHORAY_BENCH_DIR "bench"
#endif

namespace orthoray::bench {

struct Options {
    bool quick = false, smoke = false;
    std::string mode = "all"; // all, throughput, disagree, billion, embree, memory
    std::string csv;          // throughput table; -disagreement / -billion next to it
    std::string write_scenes; // a directory to write the benchmark scenes to, as .scene files
    std::string wrong_scene = std::string(ORTHORAY_BENCH_DIR) + "/float-wrong.scene";
    int runs = 5;
    int dim = 0;                      // the embree part: only 2D or 3D scenes (0: both)
    std::uint64_t steps = 0;          // exact and float steps per run (0: by mode)
    std::uint64_t scenes = 0;         // disagreement scenes (0: by mode)
    std::uint64_t billion = 0;        // steps of the long run (0: by mode)
    std::uint64_t reference_work = 0; // reference steps * elements per run (0: by mode)
};

// Throughput, preprocessing and memory on the benchmark scenes (throughput.cpp).
int throughput(const Options& o);
// The long run: peak memory does not grow with the number of reflections.
int billion(const Options& o);
// The benchmark scenes as .scene files, for `orthoray solve` and profilers.
int write_scenes(const std::string& dir);
// Float against exact on random scenes (disagreement.cpp).
int disagreements(const Options& o);
// Embree's speed and path against the exact engine's (embree_bench.cpp); a
// message only when CMake did not find Embree.
int embree_baseline(const Options& o);
// The Embree part of bench_smoke: Embree (both scene flags) runs random boxes
// to the cap without leaking and follows the exact path for its first
// reflections. Calls `fail` for each problem and returns the scenes compared
// (0 without Embree).
int embree_smoke(const std::function<void(const std::string&)>& fail);
// The machine's load latency by footprint and its cost of fresh memory
// (memory_ladder.cpp): what bounds the rows of 10^5 elements.
int memory_ladder(const Options& o);
// The ctest bench_smoke check (smoke.cpp): quick, and fails on a real problem.
int smoke();

} // namespace orthoray::bench

// The machine's memory, measured: what one dependent load costs as the data
// outgrows the caches, and what the first touch of fresh memory costs.
//
// Both bound the largest rows of issue 17 (bench/RESULTS.md). A 3D shot
// among 10^5 random mirrors, or an induction step on the exchange of 10^5
// mirrors (1.4 million pieces), reads records at positions nobody can
// predict from structures far larger than the cache, so each costs at least
// one load of the second kind below; and a setup that writes a table of
// tens of megabytes pays the first touch of every page of it, whatever its
// algorithm. Measuring them on the machine at hand turns "memory-bound"
// into a number a reader can check against the rates.
//
// Latency: a single random cycle through 64-byte nodes (Sattolo's shuffle,
// so the walk visits every node and no prefetcher can guess the next), each
// node's first word the index of the next; the time per step of a long walk
// is the latency of a load at that footprint. First touch: fresh anonymous
// memory from mmap, one byte written to every 4 KB page, with and without
// MADV_HUGEPAGE (2 MB pages where the kernel grants them).
#include "bench_util.hpp"
#include "orthoray_bench.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

namespace orthoray::bench {
namespace {

using Clock = std::chrono::steady_clock;

struct alignas(64) Node {
    std::uint64_t next;
    std::uint64_t pad[7];
};

// Nanoseconds a dependent load over `bytes` of nodes, median of `runs` walks.
double load_latency(std::size_t bytes, std::uint64_t steps, int runs) {
    const std::size_t n = bytes / sizeof(Node);
    std::vector<Node> nodes(n);
    std::vector<std::uint64_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    // Sattolo: a uniformly random permutation with a single cycle.
    std::mt19937_64 rng(17);
    for (std::size_t i = n - 1; i > 0; --i) std::swap(order[i], order[rng() % i]);
    for (std::size_t i = 0; i < n; ++i) nodes[i].next = order[i];
    std::uint64_t at = 0;
    for (std::size_t i = 0; i < n; ++i) at = nodes[at].next; // warm the caches and TLB
    std::vector<double> ns;
    for (int r = 0; r < runs; ++r) {
        const auto begin = Clock::now();
        for (std::uint64_t i = 0; i < steps; ++i) at = nodes[at].next;
        ns.push_back(std::chrono::duration<double, std::nano>(Clock::now() - begin).count() /
                     static_cast<double>(steps));
    }
    // The walk's end is printed nowhere but must not be optimized away.
    volatile std::uint64_t sink = at;
    (void)sink;
    return median(ns);
}

// Microseconds to fault in one 4 KB page of fresh memory, over `bytes`,
// median of `runs`; with `huge`, the region is offered 2 MB pages first.
double first_touch(std::size_t bytes, bool huge, int runs) {
    constexpr std::size_t page = 4096, huge_page = std::size_t{2} << 20;
    std::vector<double> us;
    for (int r = 0; r < runs; ++r) {
        const std::size_t mapped = bytes + huge_page;
        void* raw =
            mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (raw == MAP_FAILED) return -1;
        auto* region = reinterpret_cast<char*>(
            (reinterpret_cast<std::uintptr_t>(raw) + huge_page - 1) & ~(huge_page - 1));
        if (huge) madvise(region, bytes, MADV_HUGEPAGE);
        const auto begin = Clock::now();
        for (std::size_t i = 0; i < bytes; i += page) region[i] = 1;
        us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - begin).count() /
                     static_cast<double>(bytes / page));
        munmap(raw, mapped);
    }
    return median(us);
}

} // namespace

int memory_ladder(const Options& o) {
    const std::uint64_t steps = o.quick ? 1'000'000 : 5'000'000;
    const std::size_t largest_mb = o.quick ? 64 : 256;
    const int runs = std::max(1, o.runs);
    std::printf("## The machine's memory\n\n"
                "A dependent load at random positions (one cycle through 64-byte nodes, %llu "
                "steps, median of %d walks) as the footprint grows, and the first touch of fresh "
                "memory (one byte a 4 KB page of a new 64 MB mapping, median of %d).\n\n",
                static_cast<unsigned long long>(steps), runs, runs);
    std::printf("| footprint | ns a load |\n| --- | --- |\n");
    for (std::size_t mb = 1; mb <= largest_mb; mb *= 2)
        std::printf("| %zu MB | %.1f |\n", mb, load_latency(mb << 20, steps, runs));
    const std::size_t touched = std::size_t{64} << 20;
    std::printf("\n| first touch | us a 4 KB page | ms a 64 MB table |\n| --- | --- | --- |\n");
    for (const bool huge : {false, true}) {
        const double us = first_touch(touched, huge, runs);
        std::printf("| %s | %.2f | %.1f |\n", huge ? "MADV_HUGEPAGE" : "4 KB pages", us,
                    us * static_cast<double>(touched / 4096) / 1000.0);
    }
    std::printf("\n");
    return 0;
}

} // namespace orthoray::bench

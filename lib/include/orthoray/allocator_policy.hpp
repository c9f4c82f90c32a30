// How a program built on orthoray has malloc treat the memory it frees. For
// programs (the command-line tool, the benchmarks) to call first thing; the
// library never calls it, since it changes the allocator of the whole
// process, and a host such as Python may want its own.
#pragma once

namespace orthoray {

// Keeps freed memory in the process for the next allocations instead of
// returning it to the operating system.
//
// Why: setting up a large scene allocates and frees tens of megabytes of
// arrays (a sweep's events, sorted copies, the exchange's raw pieces).
// glibc serves every block over 128 kB by a fresh mapping and unmaps it when
// it is freed, so the next block is fresh memory again, and each of its
// 4 kB pages costs a page fault when it is first written. On the virtual
// machines this project runs on, a fault costs about 6 microseconds: at 10^4
// random mirrors a solve by induction took some 15,000 of them (about a fifth
// of its time), and at 10^5 mirrors the 2D tables' setup some 47,000.
// Served from the heap and never trimmed, freed blocks are reused instead
// (docs/limits.md, "Memory the process keeps"). Peak memory is the
// same high-water mark; it is simply not handed back before the process
// ends.
//
// Returns whether the policy was set: not when the environment's
// GLIBC_TUNABLES sets malloc's own (the user's choice stands), not under a
// sanitizer's allocator, and not off glibc.
bool keep_freed_memory();

} // namespace orthoray

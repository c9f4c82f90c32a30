// What a solver says about an instance.
#pragma once

#include "orthoray/number.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace orthoray {

// hit: the ray reaches the target (answer yes). escape, absorbed, cycle: it
// never does (answer no). limit: a resource limit stopped the run first.
enum class Reason { hit, escape, absorbed, cycle, limit };

// Which resource limit stopped a run (Reason::limit): the reflection cap, the
// time allowed, memory, or a request from outside (a signal such as SIGINT).
enum class Limit { steps, time, memory, interrupt };

struct Answer {
    Reason reason = Reason::limit;
    // hit: reflections strictly before the ray first reaches the target;
    // escape/absorbed: reflections before it leaves or stops; cycle: the
    // period (reflections in one period); limit: reflections performed.
    Integer reflections;
    std::string engine; // which engine decided it ("lattice", "induction", "reference", "graph")
    std::string
        arithmetic; // integers the lattice engine used ("int64", "int128", "gmp"), or "rational"
    Limit limit = Limit::steps; // which limit, when reason is Reason::limit
    std::string shooter;        // how the lattice engine found next hits: "grid", "bvh", "section",
                                // "pieces" (2D), or ""

    // What the lattice engine built before or while stepping.
    struct Setup {
        double seconds = 0;     // time spent building the grid and piece tables
        std::size_t cells = 0;  // uniform grid cells
        std::size_t pieces = 0; // piece-table pieces (0 when none were built)
    } setup;

    // What the induction engine did, when it decided (docs/induction.md).
    struct Induction {
        std::size_t pieces = 0;   // pieces of the interval exchange
        Integer states;           // states it permutes
        std::uint64_t steps = 0;  // induction steps, an accelerated one counting once
        std::uint64_t rounds = 0; // of which accelerated
        double seconds = 0;       // building the exchange and inducing
    } induction;

    bool yes() const { return reason == Reason::hit; }
    bool decided() const { return reason != Reason::limit; }
};

// "hit", "escape", "absorbed", "cycle", "limit".
const char* to_string(Reason reason);
// "steps", "time", "memory", "interrupt".
const char* to_string(Limit limit);
// "yes", "no", "unknown".
const char* answer_word(const Answer& answer);

} // namespace orthoray

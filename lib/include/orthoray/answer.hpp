// What a solver says about an instance.
#pragma once

#include "orthoray/number.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace orthoray {

// A single trajectory (one ray, one target, no splitter): hit, the ray
// reaches the target (answer yes); escape, absorbed, cycle: it never does
// (answer no). The illumination question (several rays or targets, or a
// splitter; docs/optics.md): lit, every target is lit (yes); unlit, some
// target is not (no). limit: a resource limit stopped the run first.
enum class Reason { hit, escape, absorbed, cycle, limit, lit, unlit };

// Which resource limit stopped a run (Reason::limit): the reflection cap, the
// time allowed, memory, or a request from outside (a signal such as SIGINT).
enum class Limit { steps, time, memory, interrupt };

// What the illumination question says of one target.
struct TargetAnswer {
    enum class Status { lit, unlit, unknown };
    Status status = Status::unknown;
    // lit: the least number of reflections, over all branches of all rays,
    // strictly before a branch first reaches the target.
    Integer reflections;
    // lit: the least-numbered ray (from 1, in file order) achieving it.
    std::size_t ray = 0;
    // The intensity question (docs/intensity.md), lit: the greatest
    // intensity of a branch passing the target; `reflections` and `ray` are
    // then those of one branch achieving it.
    std::optional<Integer> intensity;
    // lit after a limit: false when a branch the search had not yet walked
    // could still reach the target with fewer reflections (or from a lower
    // ray; for the intensity question, more intensely). The target is lit
    // all the same (a branch reached it), and `reflections`, `ray` and
    // `intensity` are the best found so far. Always true without a limit.
    bool best_proven = true;
};

// What actually ran, as opposed to what SolveOptions asks for (where
// "automatic" leaves the choice to the library). `none`: nothing ran, as
// when memory ran out before an engine started. `branches`: the
// illumination question's branch-state search (docs/optics.md).
enum class EngineUsed { none, lattice, induction, reference, graph, branches };
// The integers it computed with: machine ones, GMP, or rationals (the
// reference tracer and the state graph).
enum class ArithmeticUsed { none, int64, int128, gmp, rational };
// How the lattice engine found next hits; none for the other engines.
enum class ShooterUsed { none, grid, bvh, section, pieces };

struct Answer {
    Reason reason = Reason::limit;
    // hit: reflections strictly before the ray first reaches the target;
    // escape/absorbed: reflections before it leaves or stops; cycle: tail +
    // period (the cycle's start plus one period, docs/optics.md); limit:
    // reflections performed. The illumination question: the most of the lit
    // targets' least reflections (what lighting all of them so far takes).
    Integer reflections;
    // cycle: reflections before the trajectory enters its cycle (0 when it
    // is purely periodic, as it always is without one-sided elements); the
    // period is reflections - tail.
    Integer tail;
    // The illumination question: one entry per target, in file order, and
    // the number of distinct states explored (docs/optics.md, "What
    // `states` means"). Empty for a single trajectory.
    std::vector<TargetAnswer> targets;
    Integer states;
    // True when `states` is only a lower bound: a limit stopped the run, or
    // the count after the search, before every state was counted.
    bool states_lower_bound = false;
    Limit limit = Limit::steps; // which limit, when reason is Reason::limit
    EngineUsed engine = EngineUsed::none;
    ArithmeticUsed arithmetic = ArithmeticUsed::none;
    ShooterUsed shooter = ShooterUsed::none;

    // Diagnostics: what the engines built and did. They never change the answer.
    struct Stats {
        // What the lattice engine built before or while stepping.
        struct Setup {
            double seconds = 0;              // scaling to the lattice, building the grid and tables
            std::size_t cells = 0;           // uniform grid cells
            std::size_t pieces = 0;          // piece-table pieces (0 when none were built)
            std::size_t two_step_pieces = 0; // their two-step table's (0 when none was built)
        } setup;

        // What the induction engine did, when it decided, or when a limit
        // stopped it among its steps (then `rounds` is 0: not counted
        // there) (docs/induction.md).
        struct Induction {
            std::size_t pieces = 0;   // pieces of the interval exchange
            Integer states;           // states it permutes
            std::uint64_t steps = 0;  // induction steps, an accelerated one counting once
            std::uint64_t rounds = 0; // of which accelerated
            double seconds = 0;       // building the exchange and inducing
        } induction;

        // What the illumination search held and did (docs/optics.md).
        struct Illumination {
            std::uint64_t expanded = 0;  // branch states whose stretch was walked
            std::uint64_t events = 0;    // events stepped over along those stretches
            std::size_t state_bytes = 0; // bytes held for the states: set, labels, queue
        } illumination;
    } stats;

    bool yes() const { return reason == Reason::hit || reason == Reason::lit; }
    bool illumination() const { return !targets.empty(); }
    Integer period() const { return reflections - tail; }
    bool decided() const { return reason != Reason::limit; }
};

// "hit", "escape", "absorbed", "cycle", "limit".
const char* to_string(Reason reason);
// "steps", "time", "memory", "interrupt".
const char* to_string(Limit limit);
// "lattice", "induction", "reference", "graph", "branches"; "" for none.
const char* to_string(EngineUsed engine);
// "int64", "int128", "gmp", "rational"; "" for none.
const char* to_string(ArithmeticUsed arithmetic);
// "grid", "bvh", "section", "pieces"; "" for none.
const char* to_string(ShooterUsed shooter);
// "yes", "no", "unknown".
const char* answer_word(const Answer& answer);

} // namespace orthoray

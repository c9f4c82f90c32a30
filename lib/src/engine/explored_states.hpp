// The number of distinct states the illumination search explored, the
// answer's `states` (optics.md; docs/optics.md, "What `states` means").
//
// The search stores branch states only and walks each stretch keeping O(1)
// states, so the states inside stretches are counted once the search is
// over, from what each walk left: its branch state, the states it visited
// and how it ended. Adding up the stretches' lengths would count twice a
// state two stretches share, and they share states by merging: the walk is
// deterministic, so two stretches that meet in a state coincide from there
// to their common end, the same last state before the same junction, escape
// or absorption, or the same cycle entered at the same state. Between
// two-sided axis-aligned elements the step is injective on states after
// events, so
// stretches of states leaving junctions never merge; but a ray may start
// between events, and the state after its first event may be in another
// stretch too. One-sided elements and diagonals send two states to one, and
// stretches merge anywhere.
//
// So the stretches are grouped by their end, and each group of two or more
// is walked again in lockstep, aligned at that end. A state's distance to
// the end is a function of the state (the walk from it is determined), so
// the state d steps before the end of one stretch can only equal the state
// d steps before the end of another, and once two walks agree they agree to
// the end. Counting, at each distance, the walks still apart gives the
// group's union exactly, holding one state a walk. A stretch that ends in a
// cycle is cut at the state where it enters the cycle: its tail is grouped
// by that entry state, and the cycle is counted once, however many
// stretches enter it.
//
// Every comparison is exact (rationals). Hashes only choose the groups: two
// stretches grouped together by a collision never agree in the lockstep and
// are counted apart, as they must be.
#pragma once

#include "engine/byte_budget.hpp"
#include "engine/event_stepper.hpp"
#include "engine/stretch.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace orthoray::engine {

class BranchStateSet;

class ExploredStates {
public:
    ExploredStates(const EventStepper& stepper, ByteBudget& budget)
        : stepper_(stepper), budget_(budget) {}

    // The stretch of branch state `branch` was walked to its end (`end` is
    // not `stopped`). False, with nothing kept, when the budget has no room.
    bool walked(std::uint32_t branch, const StretchEnd& end);

    // The distinct states of the stretches walked to their end, together
    // with every other branch state of `branches` (reached but not expanded,
    // or walked only in part: counted by that state alone). `ray_starts`
    // are the rays' branch states: the only branch states that can lie
    // inside another stretch (a state leaving a junction only begins one,
    // as every event at a junction ends a stretch). `keep_going` is
    // asked every few hundred steps; nullopt once it says no. Throws
    // std::bad_alloc when its arrays would pass the budget.
    std::optional<std::uint64_t> count(const BranchStateSet& branches,
                                       const std::vector<std::uint32_t>& ray_starts,
                                       const std::function<bool()>& keep_going) const;

private:
    // What one walk left, 24 bytes.
    struct Walked {
        std::uint32_t branch;
        bool cycle;
        std::uint64_t visited;
        std::uint64_t last_or_period; // hash of the last state, or the period
    };

    const EventStepper& stepper_;
    ByteBudget& budget_;
    std::vector<Walked> walked_;
};

} // namespace orthoray::engine

// Rauzy induction with Zorich acceleration on an interval exchange whose
// first point x is pinned: the orbit of x decided in about k log N steps
// instead of its length.
//
// The induced map on [0, L) has pieces with a length l, a return time r (steps
// of the original map until the orbit of any point of the piece re-enters
// [0, L)) and the first event on that orbit segment, if any. Each step cuts
// the end of the domain off: let D be the piece whose domain ends at L and R
// the one whose image ends at L.
// - top (l_D > l_R): R's image lands in the cut part of D, so R becomes
//   "R, then D"; D loses l_R.
// - bottom (l_R > l_D): the last l_D points of R land in D, which is cut off;
//   they become a piece "R, then D" in D's place; R loses l_D.
// - equal: R becomes "R, then D" and D disappears; if D = R, D maps its own
//   tail onto itself, never meets x and is dropped.
// x is never cut since it is first. When L = 1 its piece is its whole orbit:
// its event is the answer, or its return time is the period.
//
// Acceleration: a run of top steps with the same D consumes the pieces after
// D in image order one by one; if their total S is less than l_D, whole
// rounds through all of them repeat, floor((l_D - 1) / S) of them at once
// (likewise for bottom runs). Each step is O(1) on two linked orders and the
// lengths; positions are never stored (the checker keeps them instead).
#pragma once

#include "induction/interval_exchange.hpp"

#include <cstdint>
#include <functional>
#include <optional>

namespace orthoray::induction {

enum class EventKind : std::uint8_t { none, hit, escape, absorbed };

// Receives every step, in the words of docs/induction-certificates.md.
class StepSink {
public:
    virtual ~StepSink() = default;
    virtual void top(std::size_t d, std::size_t r) = 0;
    virtual void bottom(std::size_t r, std::size_t d) = 0;
    virtual void equal(std::size_t r, std::size_t d) = 0;
    virtual void invariant(std::size_t d) = 0;
    virtual void top_cycle(std::size_t d, const Integer& rounds) = 0;
    virtual void bottom_cycle(std::size_t r, const Integer& rounds) = 0;
};

struct OrbitOfFirst {
    EventKind event = EventKind::none;
    Integer offset;              // the event happens at T^offset(x)
    Integer period;              // the return time of x (meaningful without an event)
    std::uint64_t steps = 0;     // steps taken, a cycle step counting once
    std::uint64_t rounds = 0;    // of which accelerated (cycle) steps
    const char* arithmetic = ""; // the integers it ran on: "int64", "int128" or "gmp"
};

// Decides the orbit of x = 0. `stop` is asked every few thousand steps and
// ends the run (std::nullopt) when it returns true.
std::optional<OrbitOfFirst> induce(const IntervalExchange& exchange, StepSink* sink,
                                   const std::function<bool(std::uint64_t)>& stop);

} // namespace orthoray::induction

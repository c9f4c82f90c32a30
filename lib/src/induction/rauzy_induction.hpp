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

#include "orthoray/exchange.hpp"

#include <cstdint>
#include <functional>
#include <optional>

namespace orthoray::induction {

// Decides the orbit of x = 0. `stop` is asked every few thousand steps and
// ends the run (std::nullopt) when it returns true.
// Every step goes to `observer`, if any (begin() is the caller's).
std::optional<InducedOrbit> induce(const IntervalExchange& exchange, InductionObserver* observer,
                                   const std::function<bool(std::uint64_t)>& stop);
// The same on the build's own integers (exchange_builder.hpp), unconverted.
template <class Num>
struct ExchangeOn;
template <class Num>
std::optional<InducedOrbit> induce(const ExchangeOn<Num>& exchange,
                                   const std::function<bool(std::uint64_t)>& stop);

} // namespace orthoray::induction

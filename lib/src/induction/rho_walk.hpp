// Deciding an orbit of a step map T that is not injective, by Rauzy-Zorich
// induction between its special states (docs/induction.md, "Two states
// stepping to one").
//
// T agrees with an interval exchange E (collisions.hpp: the collisions'
// states cut out) everywhere but on the cut states. The *special* states
// are x, the cut states and the joins. The walk induces on E from its
// current state p with every special state but p marked, so each induction
// ends at the next special state on the orbit (found among the marks by
// halving them), at an event, or back at p; at a cut state it takes T's
// step to the join by hand.
//
// Why the first repeated special state gives tail and period. Let the
// orbit s_1 = x, s_2, ... of T enter its cycle at s_mu, with period
// lambda. If mu > 1, s_mu has two preimages (s_{mu-1} off the cycle,
// s_{mu-1+lambda} on it), so it is a join; if mu = 1 it is x: either way
// special. Let z be the first special state the walk sees twice, at times
// t0 < t1 (time t: s_{t+1}). z lies on the cycle, so t1 - t0 = lambda. Had
// the orbit entered the cycle before t0, its entry (special) would recur
// at mu - 1 + lambda, strictly between t0 and t1, and would have been seen
// twice first. So mu - 1 = t0: the tail is t0.
//
// On a double cover this is the lifted orbit, and the twin (other lift) of
// every special state is marked too. The lifted tail is the physical one: a
// physical repeat s_i = s_j puts the lift at time j on s_i's lift or on its
// twin, the lift commutes with the twin map, so the lift repeats by time
// j + lambda; and a lifted repeat is a physical one. The physical period is
// the lifted one or half of it, half exactly when z's twin (marked, so
// seen) comes half a lifted period after z.
//
// Every induction runs on E re-rooted at its start (`reroot`): the pieces
// of E as the certificate lists them (rotated so that x is 0), cut at the
// start and at each mark, rotated so that the start is 0. The verifier
// builds the same pieces from the certificate's list, so the steps it
// replays name the same pieces (docs/induction-certificates.md, "The
// walk").
#pragma once

#include "induction/exchange_builder.hpp"
#include "orthoray/exchange.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace orthoray::induction {

// The step map, in the coordinates of E's listing (x = 0).
struct RhoMap {
    ExchangeOn<Integer> listed;                     // E; the target's states flagged hit
    std::vector<std::pair<Integer, Integer>> cuts;  // (cut state, its join), sorted
    std::vector<std::pair<Integer, Integer>> twins; // (special state, its other lift), sorted
};

// The states every `all` search marks but its start: x, the cut states,
// the joins and their twins, sorted.
std::vector<Integer> special_states(const RhoMap& map);

// One induction of the walk: from `from`, with every special state but
// `from` and the target's states marked, or with `only` marked.
struct RhoSearch {
    Integer from;
    std::optional<Integer> only;
};

struct RhoOrbit {
    ExchangeEvent event = ExchangeEvent::none;
    Integer offset;       // the event happens at T^offset(x)
    Integer tail, period; // without an event: the cycle, as Answer counts it
    std::uint64_t steps = 0, rounds = 0;
    // The inductions a certificate needs, in order: each `all` search and,
    // when it met a mark, the `only` search that names the mark.
    std::vector<RhoSearch> proof;
};

// E re-rooted at `from` with `marks` flagged hit (and the listing's own hit
// flags kept when `keep_hits`).
ExchangeOn<Integer> reroot(const ExchangeOn<Integer>& listed, const Integer& from,
                           const std::vector<Integer>& marks, bool keep_hits);

// The exchange of one search of the proof.
ExchangeOn<Integer> search_exchange(const RhoMap& map, const RhoSearch& search);

// Nothing when `stop` ended an induction.
std::optional<RhoOrbit> walk_rho(const RhoMap& map, const std::function<bool(std::uint64_t)>& stop);

} // namespace orthoray::induction

// Deciding an orbit of a step map T that is not injective, by Rauzy-Zorich
// induction between its special states (docs/induction.md, "Two states
// stepping to one").
//
// T agrees with an interval exchange E (collisions.hpp: the collisions'
// states cut out) everywhere but on the cut states. The *special* states
// are x, the cut states, the joins, and on a double cover the other lift
// of each. The walk induces on E from its current state p with every
// special state but p marked, so each induction ends at the next special
// state on the orbit (found among the marks by halving them), at an event,
// or back at p; at a cut state it takes T's step to the join by hand.
//
// Why the first repeated special state gives tail and period. Let the
// orbit s_1 = x, s_2, ... of T enter its cycle at s_mu, with period
// lambda. If mu > 1, s_mu has two preimages (s_{mu-1} off the cycle,
// s_{mu-1+lambda} on it), so it is a join; if mu = 1 it is x: either way
// special. Let z be the first special state the walk sees twice, at times
// t0 < t1 (time t: s_{t+1}). z lies on the cycle, so t1 - t0 = lambda. Had
// the orbit entered the cycle before t0, its entry (special) would recur
// at mu - 1 + lambda, strictly between t0 and t1, and would have been seen
// twice first. So mu - 1 = t0: the tail is t0 and reflections = t1.
#pragma once

#include "induction/collisions.hpp"
#include "orthoray/exchange.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace orthoray::induction {

// The step map: E's raw pieces (collisions cut), the collisions, x and its
// twin, the states whose segment passes the target.
struct RhoMap {
    Integer size, modulus;
    std::vector<RawPiece> pieces;
    std::vector<Collision> collisions;
    std::vector<std::pair<Integer, Integer>> twins; // (state, other lift), sorted
    Integer first;
    std::optional<Integer> first_twin;
    std::vector<Integer> hits; // sorted
};

struct RhoOrbit {
    ExchangeEvent event = ExchangeEvent::none;
    Integer offset;       // the event happens at T^offset(x)
    Integer tail, period; // without an event: the cycle, as Answer counts it
    std::uint64_t steps = 0, rounds = 0, inductions = 0;
};

// Nothing when `stop` ended an induction.
std::optional<RhoOrbit> walk_rho(const RhoMap& map, const std::function<bool(std::uint64_t)>& stop);

} // namespace orthoray::induction

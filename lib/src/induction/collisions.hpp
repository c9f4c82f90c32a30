// Step maps that are not injective: where two states step to one.
//
// In an octagonal maze a ray along an axis or a diagonal can slide along a
// diagonal into a vertex where an element of another orientation ends; the
// element there acts alone and sends the ray on as a ray arriving at the
// corner from the other side is sent back (docs/octagonal.md, "Meeting and
// reflecting"). Two states then step to one, the *join*. The first-return
// map is still a translation on every piece, but two pieces' images share
// that one state, and no interval exchange is the map.
//
// Cutting one preimage of every join out of the exchange (a singleton piece
// marked as a dead end, whose image the exchange then closes onto a state no
// piece maps to) leaves an honest exchange E that agrees with the step map T
// everywhere but on the cut states. rho_walk.hpp decides an orbit of T by
// inducing on E between those states.
#pragma once

#include "induction/exchange_builder.hpp"

#include <optional>
#include <vector>

namespace orthoray::induction {

// T(state) = join, and another state steps to the join as well; `state`
// is the preimage cut out of the exchange.
struct Collision {
    Integer state, join;
};

// The collisions of the raw pieces (sorted by start, tiling the states):
// for every state two or more reflecting pieces' images share, every
// preimage but the first in order of image. Nothing when two images share
// more than one state (no ray the builder knows of does that: a slide
// happens along one line, so for one w).
std::optional<std::vector<Collision>> find_collisions(const std::vector<RawPiece>& pieces);

// Cuts each collision's state out as a singleton absorbed piece: its image
// is left to the exchange's hole closing, and the orbit of E never uses it
// if the walk stops there.
void cut_collisions(std::vector<RawPiece>& pieces, const std::vector<Collision>& collisions);

} // namespace orthoray::induction

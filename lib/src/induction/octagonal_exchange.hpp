// The first-return map of an octagonal maze as an integer interval exchange
// on the eight-sheeted cover (docs/induction.md, "Octagonal mazes").
//
// A *lifted state* is a point q where the ray leaves an event and a sheet g
// of the symmetry group of the square with g v the direction it leaves in.
// Its coordinate w(q, g) = cross(v, g^-1 q) is constant along the ray, and a
// reflection in a line sends the sheet g to R g (R the line's reflection)
// and translates w by a constant of the line and g. So, on the cover, every
// piece of the first-return map is a translation: an interval exchange
// without flips. When v is generic (|a| != |b|, both nonzero) the eight
// sheets are the eight directions and the cover is the state space itself;
// when v lies on an axis or a diagonal, two sheets share each direction,
// their w differ in sign, and the cover is the orientation double cover of
// the exchange with flips that the plain positions give.
//
// The arrangement. Vertices are the elements' ends and every point where
// two of them meet; each line of the arrangement is cut at the vertices on
// it into open edges, each covered by mirrors, absorbers or nothing.
// Transversals are (edge, sheet) for the edges only mirrors cover and the
// sheets not parallel to them, and (vertex, sheet) for the sheets a ray
// can leave the vertex in: one state each. An edge transversal's states are
// the w of the orbit's class in the open range its two ends give, numbered
// by increasing w. Its pieces change only where the ray passes a vertex:
// shooting back from every vertex along every sheet finds those w. Each run
// between them is resolved by shooting from its first and its last state
// (a run that is not a translation would be a bug, and throws).
#pragma once

#include "induction/collisions.hpp"
#include "induction/exchange_builder.hpp"
#include "induction/octagonal_geometry.hpp"

#include <functional>
#include <optional>
#include <ostream>
#include <vector>

namespace orthoray::induction::octagonal {

// What the engine needs besides the exchange: the raw pieces and marks, to
// finish the exchange again with other marks (the twin, below).
struct OctagonalLayout {
    Integer size, modulus;
    std::vector<RawPiece> pieces;
    Integer first;             // raw number of x, the state after reflection 1
    std::vector<Integer> hits; // raw numbers of the states whose segment passes the target
    // On a double cover, x's other lift: T^p(x) = twin means the physical
    // orbit returned after p reflections.
    std::optional<Integer> twin;
    // The same states as lattice points, for certificates: one transversal
    // a slot in raw order, and where x (and its twin) sit in them.
    std::vector<LiftedTransversal> transversals;
    std::size_t first_slot = 0, twin_slot = 0;
    Integer first_index, twin_index;
    // Where two states step to one (collisions.hpp): empty when the step
    // map is a bijection. `pieces` are the true map, images overlapping at
    // the joins; the engine cuts the collisions' states before inducing.
    std::vector<Collision> collisions;
    // On a double cover, (raw, its other lift) for every state the
    // collisions name, sorted: the walk counts the two lifts as one
    // physical state.
    std::vector<std::pair<Integer, Integer>> twins;
};

enum class BuildFailure {
    none,
    not_injective, // two images share more than one state (collisions.hpp)
    too_large,     // more pieces than `max_pieces`
    stopped,       // `stop` said so (a time limit, a signal)
};

// x = (first_point, first_sheet) is the lifted state after reflection 1.
// With `dump`, the transversals and the raw pieces are written there too
// (`orthoray pieces` on a diagonal scene). `stop`, if set, is asked every
// few thousand units of work (sweep events, shots, runs): the build may
// take seconds on 10^4 elements.
template <class Int>
std::optional<OctagonalLayout>
build_layout(const OctagonalScene<Int>& scene, const Point<Int>& first_point, int first_sheet,
             std::size_t max_pieces, BuildFailure& failure, std::ostream* dump = nullptr,
             const std::function<bool()>& stop = {});

} // namespace orthoray::induction::octagonal

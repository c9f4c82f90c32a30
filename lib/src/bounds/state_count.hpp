// Counting the states of docs/bounds.md: integer points on the elements
// (each once) and the states among them that keep the line invariant.
#pragma once

#include "bounds/line_invariant.hpp"
#include "lattice/octagonal_lattice.hpp"

namespace orthoray::bounds {

struct StateCount {
    Integer points;  // integer points on the union of the elements
    Integer refined; // (point, direction) states keeping the start's invariant
};

// M = 1 or 2: both exact.
StateCount count_line_and_plane_states(const lattice::LatticeScene& scene,
                                       const LineInvariant& invariant);

// M = 3: points exact; refined an upper bound (on a face, the invariant
// coupling its two free coordinates is not used).
StateCount count_space_states(const lattice::LatticeScene& scene, const LineInvariant& invariant);

// A 2D scene with diagonals, on its octagonal lattice: points exact, refined
// the states (on a point, each distinct direction) with cross(w, P) = 0
// (mod N), exact.
StateCount count_octagonal_states(const lattice::OctagonalLattice& lattice);

} // namespace orthoray::bounds

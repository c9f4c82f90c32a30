// The lattice engine on a 2D scene with diagonal elements (docs/octagonal.md,
// docs/lattice.md "Diagonal elements"): one trajectory stepped on exact
// integer states (lattice point, one of eight directions), next hits from
// an exact bounding volume hierarchy, Brent's detector and a tail pass.
#pragma once

#include "orthoray/solve.hpp"

namespace orthoray::engine {

// A single trajectory of a scene with diagonals. Throws UnsupportedScene
// when options.shooter names a structure that cannot take them (grid,
// pieces, section): only the hierarchy (bvh, and automatic) can.
Answer solve_octagonal(const Scene& scene, const SolveOptions& options);

} // namespace orthoray::engine

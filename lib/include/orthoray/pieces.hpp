// The 2D piece tables (docs/piece-tables.md), printable: for every mirror and
// direction, the runs of positions that go to the same next mirror by the
// same translation. They are the interval exchange the engine steps through.
#pragma once

#include "orthoray/scene.hpp"

#include <cstddef>
#include <ostream>

namespace orthoray {

struct PieceTableSummary {
    bool available = false; // false unless the scene is 2D and both direction components move
    std::size_t mirrors = 0, pieces = 0;
};

// Writes the tables in lattice coordinates, after a header giving the scale
// factor of each axis (scene coordinate = lattice coordinate / scale).
PieceTableSummary write_piece_tables(const Scene& scene, std::ostream& out);

} // namespace orthoray

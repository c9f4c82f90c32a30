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

enum class PieceTableFormat {
    text, // one line a piece after a commented header
    json, // one object (docs/piece-tables.md, "JSON"); axis-parallel scenes only
};

// Writes the tables in lattice coordinates, after a header giving the scale
// factor of each axis (scene coordinate = lattice coordinate / scale). For a
// scene with diagonals the text is the first-return map on the eight-sheeted
// cover (docs/induction.md); JSON is not available there.
PieceTableSummary write_piece_tables(const Scene& scene, std::ostream& out,
                                     PieceTableFormat format = PieceTableFormat::text);

} // namespace orthoray

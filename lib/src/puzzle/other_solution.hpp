// For the generator (docs/puzzles.md, "Generation"): a placement other than
// the intended one that also lights every point of a level, found by the
// placement search with a node budget. Each one found tells the generator
// which point to add (one the intended placement lights and the other does
// not) or which cell to close, until no other placement is left.
#pragma once

#include "puzzle/placement_search.hpp"

#include <cstdint>

namespace orthoray::puzzle {

struct OtherSolution {
    enum class Status { none, found, limit };
    Status status = Status::limit;
    // found: a solution leaf whose placements are not just `intended`: its
    // decided cells, and blocks left to go on any of its undecided cells.
    Board leaf;
    std::uint64_t nodes = 0;
};

// Searches `level` (its blocks still to place) for a solution leaf other
// than the one holding exactly `intended` (the same level with the blocks
// placed). `none` proves `intended` is the level's only solution; `limit`
// says `max_nodes` ran out first.
OtherSolution find_other_solution(const LazorLevel& level, const LazorLevel& intended,
                                  std::uint64_t max_nodes);

} // namespace orthoray::puzzle

// For the generator (docs/puzzles.md, "Generation"): a placement other than
// the intended one that also lights every point of a level, found by the
// placement search with a node budget. Each one found tells the generator
// which point to add (one the intended placement lights and the other does
// not) or which cell to close, until no other placement is left.
#pragma once

#include "orthoray/puzzle_pieces.hpp"
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

// Whether the leaf's placements are `intended` and nothing else: one
// arrangement of the blocks left (none left, or one kind filling every
// undecided cell), which agrees with `intended` on every open cell.
bool only_intended(const LazorLevel& level, const LazorLevel& intended, const Board& leaf);

// Searches `level` (its blocks still to place) for a solution leaf other
// than the one holding exactly `intended` (the same level with the blocks
// placed), in pieces (orthoray/puzzle_pieces.hpp) run by `runner`, or on
// this thread without one: the same answer either way. `none` proves
// `intended` is the level's only solution; `limit` says `max_nodes`
// (counted as one search from the root counts them) ran out first.
OtherSolution find_other_solution(const LazorLevel& level, const LazorLevel& intended,
                                  std::uint64_t max_nodes, const LazorPieceRunner* runner);

} // namespace orthoray::puzzle

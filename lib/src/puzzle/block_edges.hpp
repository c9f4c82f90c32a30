// How a level's geometry maps to the scene (docs/puzzles.md): the one place
// that says where a block's elements are, used by lazor_scene() and by the
// search's acting table, so the two cannot disagree.
#pragma once

#include "orthoray/puzzle.hpp"

#include <array>

namespace orthoray::puzzle {

// reflect: mirror, opaque: absorber, refract: splitter.
ElementKind element_kind(LazorCell block);

// The block at (column, row) of a grid `height` blocks high: its left,
// right, bottom and top edges in scene coordinates, each one-sided and
// acting only on rays that arrive from outside the block.
std::array<Element, 4> block_edges(LazorCell block, int column, int row, int height);

// A file position (half-block units, y downward) in scene coordinates
// (y upward: y' = 2 * height - y), and a file direction likewise.
Vector scene_point(int x, int y, int height);
Vector scene_direction(int dx, int dy);

// The cell a laser starts from: on the other side of its start edge from
// the cell it moves into. Its index in the grid, or -1 outside the grid.
int cell_behind(const LazorLevel& level, const LazorLaser& laser);

// Whether a branch that the cell ahead of a start sends back into the cell
// behind it ends there: when that cell holds a reflect or opaque block
// (docs/puzzles.md, "Lasers that start on a block").
bool stops_branches_back(LazorCell behind);

// The element that makes it so in the scene: a one-sided absorber a quarter
// step inside the cell behind, across the path of the branch sent back.
Element start_guard(const LazorLaser& laser, int height);

} // namespace orthoray::puzzle

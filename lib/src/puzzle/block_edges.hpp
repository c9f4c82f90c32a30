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

} // namespace orthoray::puzzle

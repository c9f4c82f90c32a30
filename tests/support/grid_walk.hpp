// The puzzle's own reading of a grid maze, for the tests to hold the scene
// of docs/grid-mazes.md to: a beam steps from cell to cell, '/' and '\' turn
// it, '#' stops it, leaving the grid ends it. It shares no code with the
// library beyond the maze it walks.
#pragma once

#include "orthoray/grid.hpp"

#include <vector>

namespace orthoray::test {

struct GridWalk {
    bool absorbed = false; // else it left the grid
    GridSide exit_side = GridSide::left;
    int exit_index = 0;
    int mirror_hits = 0;  // before it left or was absorbed
    int cell_entries = 0; // cells entered, a block that stops it included
    // Per cell (row by row): the mirror hits before the beam first reached
    // the cell's centre, or -1 when it never did (a block's centre never is).
    std::vector<int> first_reached;
};

GridWalk walk_grid(const GridMaze& maze, const GridBeam& beam);

} // namespace orthoray::test

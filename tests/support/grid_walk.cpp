#include "support/grid_walk.hpp"

#include <stdexcept>

namespace orthoray::test {

GridWalk walk_grid(const GridMaze& maze, const GridBeam& beam) {
    GridWalk walk;
    walk.first_reached.assign(maze.cells.size(), -1);
    // Rows grow downward here, as the puzzles draw them.
    int r = 0, c = 0, dr = 0, dc = 0;
    switch (beam.side) {
    case GridSide::left:
        r = beam.index, dc = 1;
        break;
    case GridSide::right:
        r = beam.index, c = maze.width - 1, dc = -1;
        break;
    case GridSide::top:
        c = beam.index, dr = 1;
        break;
    case GridSide::bottom:
        c = beam.index, r = maze.height - 1, dr = -1;
        break;
    }
    // A beam from outside never cycles: each (cell, direction) is entered
    // at most once, since the walk can be run backwards.
    const long most = 4L * maze.width * maze.height + 1;
    while (r >= 0 && r < maze.height && c >= 0 && c < maze.width) {
        if (++walk.cell_entries > most) throw std::logic_error("walk_grid: a beam went round");
        const GridCell cell = maze.at(r, c);
        if (cell == GridCell::block) {
            walk.absorbed = true;
            return walk;
        }
        int& first = walk.first_reached[static_cast<std::size_t>(r * maze.width + c)];
        if (first < 0) first = walk.mirror_hits;
        if (cell == GridCell::rising) { // right turns up, down turns left
            const int t = dr;
            dr = -dc, dc = -t;
            ++walk.mirror_hits;
        } else if (cell == GridCell::falling) { // right turns down, up turns left
            const int t = dr;
            dr = dc, dc = t;
            ++walk.mirror_hits;
        }
        r += dr, c += dc;
    }
    walk.exit_side = r < 0              ? GridSide::top
                     : r >= maze.height ? GridSide::bottom
                     : c < 0            ? GridSide::left
                                        : GridSide::right;
    walk.exit_index = r < 0 || r >= maze.height ? c : r;
    return walk;
}

} // namespace orthoray::test

// Grid mirror mazes (.grid files): the puzzle convention of a rectangle of
// cells holding '/' and '\' mirrors and '#' blocks, with a beam entering
// from a border cell along a row or column. Reading them, and turning one
// into a scene of diagonal mirrors and absorbers (docs/octagonal.md) that
// `solve` decides. The format, the frame and the limits are in
// docs/grid-mazes.md.
#pragma once

#include "orthoray/scene.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace orthoray {

// What a cell holds: nothing ('.'), a two-sided mirror on a diagonal ('/'
// rising to the right, '\' falling), or a block ('#': absorbs on all four
// sides).
enum class GridCell : std::uint8_t { empty, rising, falling, block };

// The four sides of the grid, as a file names them.
enum class GridSide : std::uint8_t { left, right, top, bottom };

// A beam enters through the border edge of a border cell, moving inward:
// `left R` enters row R moving right, `top C` enters column C moving down.
// Rows count from 0 at the top, columns from 0 at the left.
struct GridBeam {
    GridSide side = GridSide::left;
    int index = 0;
    int line = 0;
};

// A point the question asks about: the centre of cell (row, column), or an
// exit, the way out through the border edge of a border cell (docs/grid-mazes.md).
struct GridTarget {
    enum class Kind : std::uint8_t { cell, exit };
    Kind kind = Kind::cell;
    int row = 0, column = 0; // cell
    GridSide side = GridSide::left;
    int index = 0; // exit
    int line = 0;
};

struct GridMaze {
    int width = 0, height = 0;   // columns, rows
    std::vector<GridCell> cells; // row by row from the top, width * height
    std::vector<GridBeam> beams; // at least one
    std::vector<GridTarget> targets;
    int first_row_line = 0; // the line of row 0 in its file

    GridCell at(int row, int column) const { return cells[row * width + column]; }
};

// The most mirrors and blocks a maze may hold: each becomes one to four
// elements of exact rationals, and a million of them already make a scene
// of a few hundred megabytes.
constexpr int grid_max_filled_cells = 1 << 20;

// Parses .grid text; `file` is only used in messages. Bad input throws
// InputError (orthoray/parse.hpp): `FILE:LINE:COL: found ..., expected ...`.
GridMaze read_grid_maze(std::string_view text, const std::string& file = "<input>");

// The maze as a 2D scene, in the frame of docs/grid-mazes.md: cell (r, c) is
// the unit square [c, c + 1] x [H - r - 1, H - r] (y up); '/' is the mirror
// from (c, H - r - 1) to (c + 1, H - r), '\' from (c, H - r) to
// (c + 1, H - r - 1); '#' is an absorber on each side that no other block
// shares. A beam starts at the centre of the cell just outside its entry
// edge. A cell target is the cell's centre, an exit target the far edge of
// the cell just outside the exit edge. Without targets the scene's target is
// the grid's corner (0, 0), which no beam passes, so solve() says how the
// beam ends.
Scene grid_scene(const GridMaze& maze);

// "left", "right", "top", "bottom".
const char* to_string(GridSide side);

} // namespace orthoray

// A grid maze as a scene (docs/grid-mazes.md). The frame puts every beam on
// a line through cell centres: a beam along a row has y = H - r - 1/2, one
// along a column x = c + 1/2, and a mirror turns it at the cell's centre,
// onto another such line. So every event lies at a cell centre or at the
// midpoint of a block's side, never at a cell corner, where mirrors and
// block sides of different orientations meet: the puzzle's cell-by-cell
// reading and the scene's exact one agree.
#include "orthoray/grid.hpp"

namespace orthoray {
namespace {

const Rational half(1, 2);

bool is_block(const GridMaze& maze, int row, int column) {
    return row >= 0 && row < maze.height && column >= 0 && column < maze.width &&
           maze.at(row, column) == GridCell::block;
}

// The sides of block (r, c) that no other block shares: a shared side lies
// inside the blocks, where no beam gets.
void add_block(Scene& scene, const GridMaze& maze, int r, int c) {
    const Rational x0(c), x1(c + 1), y0(maze.height - r - 1), y1(maze.height - r);
    if (!is_block(maze, r, c - 1)) scene.add_absorber(0, x0, {{y0, y1}});
    if (!is_block(maze, r, c + 1)) scene.add_absorber(0, x1, {{y0, y1}});
    if (!is_block(maze, r + 1, c)) scene.add_absorber(1, y0, {{x0, x1}});
    if (!is_block(maze, r - 1, c)) scene.add_absorber(1, y1, {{x0, x1}});
}

// Where the line through the centres of row or column `index` meets the
// side of the grid, `outward` cells beyond that side (0: on the border).
Vector beyond(const GridMaze& maze, GridSide side, int index, const Rational& outward) {
    const Rational along_row = Rational(maze.height - index) - half; // y of row `index`
    const Rational along_column = Rational(index) + half;            // x of column `index`
    switch (side) {
    case GridSide::left:
        return {-outward, along_row, Rational(0)};
    case GridSide::right:
        return {Rational(maze.width) + outward, along_row, Rational(0)};
    case GridSide::top:
        return {along_column, Rational(maze.height) + outward, Rational(0)};
    case GridSide::bottom:
        return {along_column, -outward, Rational(0)};
    }
    return {};
}

// Inward from the side.
Vector inward(GridSide side) {
    switch (side) {
    case GridSide::left:
        return {Rational(1), Rational(0), Rational(0)};
    case GridSide::right:
        return {Rational(-1), Rational(0), Rational(0)};
    case GridSide::top:
        return {Rational(0), Rational(-1), Rational(0)};
    case GridSide::bottom:
        return {Rational(0), Rational(1), Rational(0)};
    }
    return {};
}

} // namespace

Scene grid_scene(const GridMaze& maze) {
    Scene scene;
    scene.dim = 2;
    scene.rays.clear();
    scene.targets.clear();
    const int h = maze.height;
    std::size_t filled = 0;
    for (GridCell cell : maze.cells)
        filled += cell == GridCell::block ? 4 : cell != GridCell::empty;
    // Rationals are not nothrow-movable: a growing vector would copy them all.
    scene.elements.reserve(filled);
    for (int r = 0; r < h; ++r) {
        for (int c = 0; c < maze.width; ++c) {
            const std::size_t before = scene.elements.size();
            switch (maze.at(r, c)) {
            case GridCell::empty:
                break;
            case GridCell::rising:
                scene.add_diagonal(ElementKind::mirror, c, h - r - 1, c + 1, h - r);
                break;
            case GridCell::falling:
                scene.add_diagonal(ElementKind::mirror, c, h - r, c + 1, h - r - 1);
                break;
            case GridCell::block:
                add_block(scene, maze, r, c);
                break;
            }
            for (std::size_t i = before; i < scene.elements.size(); ++i)
                scene.elements[i].line = maze.first_row_line + r;
        }
    }
    // A beam starts at the centre of the cell just outside its entry edge,
    // so a block at the entry absorbs it on its outer side.
    for (const GridBeam& beam : maze.beams)
        scene.rays.push_back({beyond(maze, beam.side, beam.index, half), inward(beam.side),
                              beam.line, std::nullopt});
    // An exit target lies one cell outside the grid: only a beam leaving
    // through that edge passes it (a beam entering there starts nearer).
    for (const GridTarget& target : maze.targets)
        scene.targets.push_back(target.kind == GridTarget::Kind::cell
                                    ? Vector{Rational(target.column) + half,
                                             Rational(h - target.row) - half, Rational(0)}
                                    : beyond(maze, target.side, target.index, Rational(1)));
    // Beams run on lines with one coordinate in Z + 1/2, so none passes a
    // point with both coordinates integers, such as the corner (0, 0).
    if (scene.targets.empty()) scene.targets.push_back(Vector{});
    return scene;
}

} // namespace orthoray

// Grid mazes (docs/grid-mazes.md): the .grid reader, the exact scene of a
// maze, one message for each kind of bad input, and the command line's
// convert and solve on .grid files.
#include "orthoray/grid.hpp"
#include "orthoray/parse.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace orthoray;
using namespace orthoray::test;

namespace {

std::string message_of(const std::string& text) {
    try {
        read_grid_maze(text, "m.grid");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(read without error)";
}

std::string scene_text(const std::string& grid) {
    return write_scene(grid_scene(read_grid_maze(grid, "m.grid")));
}

} // namespace

TEST_CASE("a grid file may start with a UTF-8 byte order mark", "[grid][reader]") {
    const std::string plain = "beam left 0\ntarget 0 1\ngrid\n./\n";
    const GridMaze marked = read_grid_maze("\xEF\xBB\xBF" + plain, "m.grid");
    const GridMaze expected = read_grid_maze(plain, "m.grid");
    CHECK(marked.cells == expected.cells);
    CHECK(marked.width == 2);
    CHECK(marked.first_row_line == 4);
    REQUIRE(marked.beams.size() == 1);
    CHECK(marked.beams[0].side == GridSide::left);
    // The mark counts as three columns of line 1.
    CHECK_THROWS_WITH(read_grid_maze("\xEF\xBB\xBF"
                                     "beam nowhere 0\n",
                                     "m.grid"),
                      Catch::Contains("m.grid:1:9:"));
}

TEST_CASE("a grid reads cell by cell, its statements in order", "[grid][reader]") {
    const GridMaze maze = read_grid_maze("# a comment\n"
                                         "beam left 1   # enters row 1\n"
                                         "target 0 2\n"
                                         "exit top 0\n"
                                         "beam bottom 2\n"
                                         "grid\n"
                                         "./\\\n"
                                         "#..\r\n"
                                         "\n\n");
    CHECK(maze.width == 3);
    CHECK(maze.height == 2);
    CHECK(maze.first_row_line == 7);
    CHECK(maze.cells == std::vector<GridCell>{GridCell::empty, GridCell::rising, GridCell::falling,
                                              GridCell::block, GridCell::empty, GridCell::empty});
    REQUIRE(maze.beams.size() == 2);
    CHECK(maze.beams[0].side == GridSide::left);
    CHECK(maze.beams[0].index == 1);
    CHECK(maze.beams[0].line == 2);
    CHECK(maze.beams[1].side == GridSide::bottom);
    CHECK(maze.beams[1].index == 2);
    REQUIRE(maze.targets.size() == 2);
    CHECK(maze.targets[0].kind == GridTarget::Kind::cell);
    CHECK(maze.targets[0].row == 0);
    CHECK(maze.targets[0].column == 2);
    CHECK(maze.targets[1].kind == GridTarget::Kind::exit);
    CHECK(maze.targets[1].side == GridSide::top);
    CHECK(maze.targets[1].index == 0);
}

TEST_CASE("a maze's scene: mirrors on cell diagonals, beams and targets on centre lines",
          "[grid][scene]") {
    // H = 2: row 0 is y in [1, 2], row 1 is y in [0, 1].
    CHECK(scene_text("beam left 0\n"
                     "target 1 1\n"
                     "exit bottom 0\n"
                     "grid\n"
                     "/\\\n"
                     "#.\n") == "dim 2\n"
                                "mirror / 0 1 1 2\n"
                                "mirror \\ 1 2 2 1\n"
                                "absorber x 0 y 0 1\n"
                                "absorber x 1 y 0 1\n"
                                "absorber y 0 x 0 1\n"
                                "absorber y 1 x 0 1\n"
                                "ray -1/2 3/2 1 0\n"
                                "target 3/2 1/2\n"
                                "target 1/2 -1\n");
}

TEST_CASE("blocks share no sides, and each side of the grid sends its beam inward",
          "[grid][scene]") {
    // Without a target, the scene's target is the corner (0, 0).
    CHECK(scene_text("beam left 0\nbeam right 1\nbeam top 2\nbeam bottom 0\n"
                     "exit left 1\nexit right 0\nexit top 1\nexit bottom 2\n"
                     "grid\n"
                     "##.\n"
                     ".#.\n") == "dim 2\n"
                                 "absorber x 0 y 1 2\n"
                                 "absorber y 1 x 0 1\n"
                                 "absorber y 2 x 0 1\n"
                                 "absorber x 2 y 1 2\n"
                                 "absorber y 2 x 1 2\n"
                                 "absorber x 1 y 0 1\n"
                                 "absorber x 2 y 0 1\n"
                                 "absorber y 0 x 1 2\n"
                                 "ray -1/2 3/2 1 0\n"
                                 "ray 7/2 1/2 -1 0\n"
                                 "ray 5/2 5/2 0 -1\n"
                                 "ray 1/2 -1/2 0 1\n"
                                 "target -1 1/2\n"
                                 "target 4 3/2\n"
                                 "target 3/2 3\n"
                                 "target 5/2 -1\n");
    CHECK(scene_text("beam top 0\ngrid\n.\n") == "dim 2\nray 1/2 3/2 0 -1\ntarget 0 0\n");
}

TEST_CASE("the scene remembers the line of each element's row", "[grid][scene]") {
    const Scene scene = grid_scene(read_grid_maze("beam left 0\ngrid\n..\n./\n#.\n"));
    REQUIRE(scene.elements.size() == 5);
    CHECK(scene.elements[0].line == 4);
    for (std::size_t i = 1; i < 5; ++i) CHECK(scene.elements[i].line == 5);
    CHECK(scene.rays[0].line == 1);
}

TEST_CASE("bad grids give one message at the offending place", "[grid][reader]") {
    const auto [text, message] = GENERATE(table<std::string, std::string>({
        {"", "m.grid:1:1: found end of file, expected a line 'grid' followed by the rows of "
             "the maze"},
        {"beam left 0\n", "m.grid:2:1: found end of file, expected a line 'grid' followed by the "
                          "rows of the maze"},
        {"beam left 0\ngrid\n", "m.grid:3:1: found end of file, expected a row of cells after "
                                "'grid'"},
        {"target 0 0\ngrid\n.\n", "m.grid:2:1: found 'grid', expected a 'beam SIDE INDEX' "
                                  "statement first"},
        {"beam left 0\ngrid\n...\n..\n", "m.grid:4:3: found end of line, expected 3 cells, as in "
                                         "the first row on line 3"},
        {"beam left 0\ngrid\n..\n...\n", "m.grid:4:3: found '.', expected the end of the row (2 "
                                         "cells, as in the first row on line 3)"},
        {"beam left 0\ngrid\n..\n\n..\n", "m.grid:4:1: found an empty line inside the grid, "
                                          "expected a cell: . (empty), / or \\ (mirrors), # "
                                          "(block)"},
        {"beam left 0\ngrid\n.x\n", "m.grid:3:2: found 'x', expected a cell: . (empty), / or \\ "
                                    "(mirrors), # (block)"},
        {"beam left 0\ngrid\n. \n", "m.grid:3:2: found ' ', expected a cell: . (empty), / or \\ "
                                    "(mirrors), # (block)"},
        {"beam left 0\ngrid\n.|\n", "m.grid:3:2: found '|', a puzzle splitter that sends a beam "
                                    "both ways (not optics, docs/grid-mazes.md), expected a "
                                    "cell: . (empty), / or \\ (mirrors), # (block)"},
        {"beam left 0\ngrid\n\t\n", "m.grid:3:1: found byte 0x09, expected a cell: . (empty), / "
                                    "or \\ (mirrors), # (block)"},
        {"beam left 0\ngrid\n.\x80\n", "m.grid:3:2: found byte 0x80, expected a cell: . (empty), "
                                       "/ or \\ (mirrors), # (block)"},
        {"beam left 0 \x01\n", "m.grid:1:13: found byte 0x01, expected printable ASCII text"},
        {"beam up 0\n", "m.grid:1:6: found 'up', expected a side: left, right, top or bottom"},
        {"beam left\n", "m.grid:1:10: found end of line, expected a row number (0 for the top "
                        "row)"},
        {"beam top -1\n", "m.grid:1:10: found '-1', expected a column number (0 for the left "
                          "column)"},
        {"beam top 1234567890\n", "m.grid:1:10: found '1234567890', expected a column number (0 "
                                  "for the left column)"},
        {"beam left 0 1\n", "m.grid:1:13: found '1', expected end of line"},
        {"ray 0 0 1 0\n", "m.grid:1:1: found 'ray', expected a statement: beam SIDE INDEX, "
                          "target ROW COLUMN, exit SIDE INDEX, or grid"},
        {"beam left 2\ngrid\n..\n..\n", "m.grid:1:11: found row 2, expected a row from 0 to 1 "
                                        "(the grid has 2 rows)"},
        {"beam bottom 0\ntarget 0 5\ngrid\n..\n", "m.grid:2:10: found column 5, expected a "
                                                  "column from 0 to 1 (the grid has 2 columns)"},
        {"beam left 0\nexit right 1\ngrid\n..\n", "m.grid:2:12: found row 1, expected a row "
                                                  "from 0 to 0 (the grid has 1 row)"},
    }));
    CAPTURE(text);
    CHECK(message_of(text) == message);
}

TEST_CASE("a grid with more mirrors and blocks than the cap is refused at the first too many",
          "[grid][reader]") {
    // 1024 columns, 1025 rows: the first 1024 rows hold 2^20 mirrors.
    std::string text = "beam left 0\ngrid\n";
    for (int r = 0; r < 1025; ++r) text += std::string(1024, '/') + '\n';
    const std::string m = message_of(text);
    CHECK(m == "m.grid:1027:1: found mirror or block number 1048577, expected at most 1048576 "
               "(docs/grid-mazes.md)");
}

TEST_CASE("convert writes a maze's scene; it does not write a grid", "[grid][cli]") {
    TempDir dir;
    const std::string maze = dir.write("m.grid", "beam left 0\nexit right 0\ngrid\n\\.\n./\n");
    const std::string out = dir.path("m.scene");
    const CliResult r = run_cli("convert --quiet " + quote(maze) + ' ' + quote(out));
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(slurp(out) == "dim 2\n"
                        "mirror \\ 0 2 1 1\n"
                        "mirror / 1 0 2 1\n"
                        "ray -1/2 3/2 1 0\n"
                        "target 3 3/2\n");
    // The same through JSON and back: nothing is lost.
    const std::string json = dir.path("m.json");
    CHECK(run_cli("convert --quiet " + quote(maze) + ' ' + quote(json)).status == 0);
    CHECK(run_cli("convert --quiet " + quote(json) + ' ' + quote(dir.path("back.scene"))).status ==
          0);
    CHECK(slurp(dir.path("back.scene")) == slurp(out));
    // --from grid reads a maze whatever its name.
    const std::string renamed = dir.write("m.txt", slurp(maze));
    CHECK(
        run_cli("convert --quiet --from grid " + quote(renamed) + ' ' + quote(dir.path("r.scene")))
            .status == 0);
    CHECK(slurp(dir.path("r.scene")) == slurp(out));

    const CliResult refused = run_cli("convert " + quote(out) + ' ' + quote(dir.path("x.grid")));
    CHECK(refused.status == 2);
    CHECK(refused.out.empty());
    CHECK(refused.err.find("expected a name for a .scene or JSON scene, or --to scene|json") !=
          std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir.path("x.grid")));
    CHECK(run_cli("convert " + quote(out) + ' ' + quote(dir.path("y")) + " --to grid").status == 2);
}

TEST_CASE("solve reports a bad grid with its position and nothing on stdout", "[grid][cli]") {
    TempDir dir;
    const std::string maze = dir.write("bad.grid", "beam left 0\ngrid\n./\n.-\n");
    const CliResult r = run_cli("solve --json " + quote(maze));
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err == maze + ":4:2: found '-', a puzzle splitter that sends a beam both ways (not "
                          "optics, docs/grid-mazes.md), expected a cell: . (empty), / or \\ "
                          "(mirrors), # (block)\n");
}

TEST_CASE("batch takes a .grid file as an instance, not as a manifest", "[grid][cli]") {
    TempDir dir;
    dir.write("m.grid", "beam left 0\ntarget 0 1\ntarget 0 0\ngrid\n.\\\n..\n");
    const std::string out = dir.path("r.jsonl");
    const CliResult r = run_cli("batch " + quote(dir.path("m.grid")) + " -o " + quote(out));
    CHECK(r.status == 0);
    const std::string results = slurp(out);
    CHECK(results.find("\"answer\":\"yes\",\"reason\":\"lit\"") != std::string::npos);
    CHECK(std::count(results.begin(), results.end(), '\n') == 1);
}

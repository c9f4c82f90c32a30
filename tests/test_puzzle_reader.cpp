// The .bff reader: every public level and every dialect it uses, the round
// trip through the writer, placements, and one exact message for each
// malformed file (docs/puzzles.md, "The file").
#include "orthoray/parse.hpp"
#include "orthoray/puzzle.hpp"
#include "support/lazor_levels.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>

using namespace orthoray;
using namespace orthoray::test;

namespace {

std::string grid_text(const LazorLevel& level) {
    return write_lazor_grid(level);
}

void check_same(const LazorLevel& a, const LazorLevel& b) {
    CHECK(a.width == b.width);
    CHECK(a.height == b.height);
    CHECK(a.cells == b.cells);
    CHECK(a.blocks == b.blocks);
    REQUIRE(a.lasers.size() == b.lasers.size());
    for (std::size_t i = 0; i < a.lasers.size(); ++i) {
        CHECK(a.lasers[i].x == b.lasers[i].x);
        CHECK(a.lasers[i].y == b.lasers[i].y);
        CHECK(a.lasers[i].dx == b.lasers[i].dx);
        CHECK(a.lasers[i].dy == b.lasers[i].dy);
    }
    REQUIRE(a.points.size() == b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i) {
        CHECK(a.points[i].x == b.points[i].x);
        CHECK(a.points[i].y == b.points[i].y);
    }
}

std::string message_of(const std::string& text) {
    try {
        read_lazor_level(text, "f.bff");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(read without error)";
}

} // namespace

TEST_CASE("every public level reads and survives the writer", "[puzzle][reader]") {
    const auto folder = lazor_folder_or_skip();
    if (!folder) return;
    std::vector<std::filesystem::path> files = bff_files(*folder);
    for (const auto& f : bff_files(*folder / "unsolvable")) files.push_back(f);
    CHECK(files.size() == 168);
    for (const auto& file : files) {
        INFO(file.string());
        const LazorLevel level = load_lazor_level(file.string());
        CHECK(level.width >= 2);
        CHECK(level.height >= 2);
        CHECK(!level.lasers.empty());
        CHECK(!level.points.empty());
        check_same(read_lazor_level(write_lazor_level(level, "round trip")), level);
    }
}

TEST_CASE("the dialects of the public files and the issue read alike", "[puzzle][reader]") {
    const LazorLevel plain = read_lazor_level("GRID START\no o x\nA B C\nGRID STOP\nA 1\nB 1\n"
                                              "L 0 1 1 1\nP 6 3\n");
    // Rows without spaces, lowercase keywords and cells, counts in another
    // order, comments after statements, tabs, CRLF, blank lines in the grid.
    const LazorLevel dialect = read_lazor_level(
        "# a level\r\n\r\ngrid start\r\noox # first row\r\n\r\n\ta b c\r\ngrid stop\r\n"
        "b 1\r\na 1   # counts in any order\r\nl 0 1 1 1\r\np 6 3");
    check_same(dialect, plain);
    CHECK(plain.width == 3);
    CHECK(plain.height == 2);
    CHECK(plain.blocks == std::array<int, 3>{1, 1, 0});
    CHECK(grid_text(plain) == "GRID START\no o x\nA B C\nGRID STOP\n");
    // A UTF-8 byte order mark before the first line is skipped; its three
    // bytes still count in the columns. Elsewhere it is a foreign byte.
    check_same(read_lazor_level("\xEF\xBB\xBFGRID START\no o x\nA B C\nGRID STOP\nA 1\nB 1\n"
                                "L 0 1 1 1\nP 6 3\n"),
               plain);
    CHECK_THROWS_WITH(read_lazor_level("\xEF\xBB\xBFGRID BEGIN\n", "f.bff"),
                      Catch::Contains("f.bff:1:9: found"));
    CHECK_THROWS_WITH(read_lazor_level("GRID START\n\xEF\xBB\xBFo o\n", "f.bff"),
                      Catch::Contains("f.bff:2:1: found byte 0xEF"));
    // A count of zero is a count.
    CHECK(read_lazor_level("GRID START\no o\nGRID STOP\nB 0\nL 1 0 1 1\nP 1 2\n").blocks ==
          std::array<int, 3>{0, 0, 0});
}

TEST_CASE("each malformed public file gets its one message", "[puzzle][reader]") {
    const auto folder = lazor_folder_or_skip();
    if (!folder) return;
    const std::vector<std::pair<std::string, std::string>> expected{
        {"grid_1.bff", "4:9: found a 5th cell, expected 4 cells like the first row (line 2)"},
        {"grid_2.bff", "7:3: found '6' in the grid, expected a cell: o (open), x (no block), "
                       "A (reflect), B (opaque) or C (refract), or GRID STOP to end the grid "
                       "before the counts"},
        {"grid_3.bff", "5:7: found 'D', expected a cell: o (open), x (no block), A (reflect), "
                       "B (opaque) or C (refract)"},
        {"incomplete_1.bff", "12:1: found end of file, expected at least one point 'P x y'"},
        {"incomplete_2.bff", "1:1: found 'A', expected GRID START: the grid comes first"},
        {"syntax_1.bff", "7:2: found end of line, expected the number of B blocks to place"},
        {"syntax_2.bff", "7:3: found 99, expected a number of B blocks from 0 to 7 (the open "
                         "cells)"},
        {"syntax_3.bff", "9:10: found '1.5', expected the direction's y (an integer)"},
    };
    CHECK(bff_files(*folder / "malformed").size() == expected.size());
    for (const auto& [name, message] : expected) {
        const std::string path = (*folder / "malformed" / name).string();
        INFO(path);
        try {
            load_lazor_level(path);
            FAIL("read without error");
        } catch (const InputError& e) {
            CHECK(std::string(e.what()) == path + ":" + message);
        }
    }
}

TEST_CASE("bad levels name the place and what was expected", "[puzzle][reader]") {
    const std::string grid = "GRID START\no o\no o\nGRID STOP\n";
    const std::vector<std::pair<std::string, std::string>> cases{
        {grid + "L 2 2 1 1\nP 1 0\n",
         "f.bff:5:3: found the laser at (2, 2), a block corner, expected the midpoint of a cell "
         "edge (x + y odd)"},
        {grid + "L 1 1 1 1\nP 1 0\n",
         "f.bff:5:3: found the laser at (1, 1), a block centre, expected the midpoint of a cell "
         "edge (x + y odd)"},
        {grid + "L 1 0 1 1\nP 1 5\n",
         "f.bff:6:5: found 5, expected the point's y from 0 to 4 (the grid is 2 x 2 blocks, in "
         "half-block units)"},
        {grid + "L 1 0 2 1\nP 1 2\n",
         "f.bff:5:7: found 2, expected the direction's x: 1 or -1 (lasers move diagonally)"},
        {grid + "A\nL 1 0 1 1\nP 1 2\n",
         "f.bff:5:2: found end of line, expected the number of A blocks to place"},
        {grid + "A 1\nA 1\nL 1 0 1 1\nP 1 2\n",
         "f.bff:6:1: found a second count of A blocks (the first is on line 5), expected one "
         "count a block type"},
        {grid + "A 3\nC 2\nL 1 0 1 1\nP 1 2\n",
         "f.bff:6:3: found 2, expected a number of C blocks from 0 to 1 (the open cells left by "
         "the other counts)"},
        {"GRID START\no o\no o o\nGRID STOP\nL 1 0 1 1\nP 1 2\n",
         "f.bff:3:5: found a 3rd cell, expected 2 cells like the first row (line 2)"},
        {"GRID START\no o\no\nGRID STOP\nL 1 0 1 1\nP 1 2\n",
         "f.bff:3:2: found the end of the row after 1 cells, expected 2 cells like the first row "
         "(line 2)"},
        {"GRID START\no q\nGRID STOP\n",
         "f.bff:2:3: found 'q', expected a cell: o (open), x (no block), A (reflect), B (opaque) "
         "or C (refract)"},
        {"GRID START\no o\n", "f.bff:3:1: found end of file, expected GRID STOP (the grid starts "
                              "on line 1)"},
        {"GRID START\nGRID STOP\n",
         "f.bff:2:1: found GRID STOP, expected at least one row of cells"},
        {grid + "P 1 0\n",
         "f.bff:6:1: found end of file, expected at least one laser 'L x y vx vy'"},
        {grid + "Q 1\n", "f.bff:5:1: found 'Q', expected a block count (A n, B n, C n), a laser "
                         "(L x y vx vy) or a point (P x y)"},
        {grid + "GRID START\n",
         "f.bff:5:1: found a second GRID START (the grid starts on line 1), expected one grid"},
        {grid + "L 1 0 1 1 7\nP 1 2\n", "f.bff:5:11: found '7', expected end of line"},
        {"GRID START\no \xc3\xa9\nGRID STOP\n",
         "f.bff:2:3: found byte 0xC3, expected printable ASCII text"},
        {"", "f.bff:1:1: found end of file, expected a grid: GRID START, rows of cells (o x A B "
             "C), GRID STOP"},
    };
    for (const auto& [text, message] : cases) {
        INFO(text);
        CHECK(message_of(text) == message);
    }
}

TEST_CASE("a solved grid is read as a placement of the level's blocks", "[puzzle][reader]") {
    const LazorLevel level =
        read_lazor_level("GRID START\no o x\no B o\nGRID STOP\nA 1\nC 1\nL 1 0 1 1\nP 1 2\n");
    const LazorLevel solved =
        read_lazor_level("GRID START\nA o x\no B C\nGRID STOP\nL 1 0 1 1\nP 1 2\n");
    const LazorLevel placed = apply_lazor_placement(level, solved, "s.bff");
    CHECK(grid_text(placed) == "GRID START\nA o x\no B C\nGRID STOP\n");
    CHECK(placed.blocks == std::array<int, 3>{0, 0, 0});

    auto refused = [&](const std::string& grid) {
        try {
            apply_lazor_placement(level, read_lazor_level(grid + "L 1 0 1 1\nP 1 2\n"), "s.bff");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK(refused("GRID START\nA o o\no B C\nGRID STOP\n") ==
          "s.bff:2:5: found 'o' at row 1, column 3, expected the level's fixed 'x'");
    CHECK(refused("GRID START\nA A x\no B C\nGRID STOP\n") ==
          "s.bff:2:3: found a placed 'A' beyond the level's 1, expected exactly 1");
    CHECK(refused("GRID START\nA o x\no B o\nGRID STOP\n") ==
          "s.bff:3:6: found the end of the grid with 0 'C' placed on open cells, expected "
          "exactly 1");
    CHECK(refused("GRID START\no o\no B\nGRID STOP\n") ==
          "s.bff:2:1: found a grid of 2 x 2 blocks, expected the level's 3 x 2");
}

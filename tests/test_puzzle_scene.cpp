// A level as a scene (docs/puzzles.md, "The model"): the exact scene of a
// small level, what each block does, lasers that start on a block, lasers
// leaving the grid, points on corners; the acting table against the rule;
// and the search's walk, the library's engine on the scene and the plain
// rules of the tests agreeing on random placements of every public level.
#include "orthoray/puzzle.hpp"
#include "orthoray/solve.hpp"
#include "puzzle/beam_walk.hpp"
#include "support/lazor_levels.hpp"
#include "support/portable_random.hpp"

#include <catch2/catch.hpp>

using namespace orthoray;
using namespace orthoray::test;

namespace {

// Which targets of the scene the library's engine says are lit.
std::vector<bool> lit_by_solve(const Scene& scene) {
    const Answer a = solve(scene);
    REQUIRE(a.decided());
    if (!a.illumination()) return {a.yes()};
    std::vector<bool> lit;
    for (const TargetAnswer& t : a.targets) lit.push_back(t.status == TargetAnswer::Status::lit);
    return lit;
}

// Which points the search's walk passes, with every cell of `level` decided.
std::vector<bool> lit_by_walk(const LazorLevel& level) {
    std::vector<puzzle::Content> cells;
    for (const LazorCell c : level.cells)
        cells.push_back(c == LazorCell::open ? puzzle::empty : puzzle::content_of(c));
    puzzle::BeamWalk walk(level);
    CHECK(walk.walk(cells) == -1);
    return walk.lit_points();
}

// A 2 x 2 grid with `cell` at column 1, row 1 and `behind` at column 1,
// row 0; the laser and the points as given.
LazorLevel two_by_two(char behind, char cell, const std::string& rest) {
    return read_lazor_level(std::string("GRID START\no ") + behind + "\no " + cell +
                            "\nGRID STOP\n" + rest);
}

} // namespace

TEST_CASE("a small level becomes this scene", "[puzzle][scene]") {
    // One reflect block at column 1 of a 2 x 1 grid; the laser starts on
    // the grid's lower side, under the open cell, moving up and right.
    const LazorLevel level = read_lazor_level("GRID START\no A\nGRID STOP\nL 1 2 1 -1\nP 4 1\n");
    CHECK(write_scene(lazor_scene(level)) ==
          "dim 2\n"
          "mirror x- 2 y 0 2\n" // left edge: acts on rays moving right
          "mirror x+ 4 y 0 2\n" // right edge: on rays moving left
          "mirror y- 0 x 2 4\n" // bottom (the file's lower side, y = 2 there): moving up
          "mirror y+ 2 x 2 4\n" // top (the file's y = 0): moving down
          "ray 1/2 -1/2 1 1\n"  // (1, 2) in the file is (1, 0) here, half a step back
          "target 4 1\n");
}

TEST_CASE("each block acts on the laser entering it", "[puzzle][scene]") {
    // The laser enters (0, 0), then (1, 0), then meets the cell at (1, 1)
    // at (3, 2). Points: that meeting point, where a reflected branch
    // leaves the grid (4, 1), where a straight one does (4, 3), where a
    // reflected one would come back to if the grid's sides were mirrors
    // (3, 0), and a block corner (2, 2).
    const std::string rest = "L 1 0 1 1\nP 3 2\nP 4 1\nP 4 3\nP 3 0\nP 2 2\n";
    const std::vector<std::pair<char, std::vector<bool>>> cases{
        {'o', {true, false, true, false, false}},  // passes
        {'A', {true, true, false, false, false}},  // reflects
        {'B', {true, false, false, false, false}}, // absorbs
        {'C', {true, true, true, false, false}},   // both
    };
    for (const auto& [cell, lit] : cases) {
        INFO("cell " << cell);
        const LazorLevel level = two_by_two('o', cell, rest);
        CHECK(lit_by_solve(lazor_scene(level)) == lit);
        CHECK(lit_by_walk(level) == lit);
        CHECK(lazor_lit_by_rules(level) == lit);
    }
}

TEST_CASE("a laser that starts on a block is acted on as it enters", "[puzzle][scene]") {
    // The laser starts at (3, 2) into the cell (1, 1); the cell behind is
    // (1, 0). A block ahead acts at the start; a branch it sends back into
    // a reflect or opaque block behind ends there.
    const std::string rest = "L 3 2 1 1\nP 3 2\nP 4 1\nP 4 3\n";
    const std::vector<std::tuple<char, char, std::vector<bool>>> cases{
        {'o', 'o', {true, false, true}},  {'o', 'A', {true, true, false}},
        {'o', 'B', {true, false, false}}, {'o', 'C', {true, true, true}},
        {'A', 'A', {true, false, false}}, {'B', 'A', {true, false, false}},
        {'C', 'A', {true, true, false}},  {'A', 'C', {true, false, true}},
        {'B', 'C', {true, false, true}},  {'C', 'C', {true, true, true}},
        {'A', 'o', {true, false, true}},  {'B', 'B', {true, false, false}},
    };
    for (const auto& [behind, cell, lit] : cases) {
        INFO("behind " << behind << ", ahead " << cell);
        const LazorLevel level = two_by_two(behind, cell, rest);
        CHECK(lit_by_solve(lazor_scene(level)) == lit);
        CHECK(lit_by_walk(level) == lit);
        CHECK(lazor_lit_by_rules(level) == lit);
    }
}

TEST_CASE("only the block a branch enters acts, as the rule's table says", "[puzzle][scene]") {
    // The search relies on it: a block on a cell no branch enters changes
    // nothing. The table comes from engine::event_outcome on the elements.
    using puzzle::Content;
    const puzzle::ActingTable& table = puzzle::ActingTable::get();
    for (int vertical = 0; vertical < 2; ++vertical)
        for (int d = 0; d < 4; ++d) {
            const bool enters_high = vertical ? (d & 1) != 0 : (d & 2) != 0;
            for (int in = 0; in < 4; ++in)
                for (int left = 0; left < 4; ++left) {
                    const auto a = static_cast<Content>(enters_high ? left : in);
                    const auto b = static_cast<Content>(enters_high ? in : left);
                    const auto a0 = enters_high ? puzzle::empty : static_cast<Content>(in);
                    const auto b0 = enters_high ? static_cast<Content>(in) : puzzle::empty;
                    const puzzle::EdgeOutcome& o = table.at(vertical != 0, a, b, d);
                    const puzzle::EdgeOutcome& o0 = table.at(vertical != 0, a0, b0, d);
                    CHECK(o.absorbed == o0.absorbed);
                    CHECK(o.directions == o0.directions);
                }
            // And what each block does: pass, reflect across the edge,
            // absorb, or both.
            const int bounced = d ^ (vertical ? 1 : 2);
            const auto at = [&](Content c) {
                return table.at(vertical != 0, enters_high ? puzzle::empty : c,
                                enters_high ? c : puzzle::empty, d);
            };
            CHECK(at(puzzle::empty).directions == 1u << d);
            CHECK(at(puzzle::reflect).directions == 1u << bounced);
            CHECK(at(puzzle::opaque).absorbed);
            CHECK(at(puzzle::opaque).directions == 0);
            CHECK(at(puzzle::refract).directions == ((1u << d) | (1u << bounced)));
        }
}

TEST_CASE("walk, engine and plain rules agree on random placements of the public levels",
          "[puzzle][scene]") {
    const auto folder = lazor_folder_or_skip();
    if (!folder) return;
    std::mt19937_64 rng(13);
    int compared = 0;
    for (const auto& file : bff_files(*folder)) {
        const LazorLevel level = load_lazor_level(file.string());
        for (int round = 0; round < 2; ++round) {
            // Any block or none on every open cell (the counts need not
            // hold: the translation does not care).
            LazorLevel placed = level;
            placed.blocks = {};
            for (LazorCell& c : placed.cells)
                if (c == LazorCell::open && chance(rng, 40))
                    c = lazor_blocks[pick_index(rng, 0, 2)];
            INFO(file.string() << "\n" << write_lazor_grid(placed));
            const std::vector<bool> rules = lazor_lit_by_rules(placed);
            CHECK(lit_by_walk(placed) == rules);
            CHECK(lit_by_solve(lazor_scene(placed)) == rules);
            ++compared;
        }
    }
    CHECK(compared == 330);
}

// The placement search (docs/puzzles.md, "The search"): every public level
// solved with exactly its blocks and each solution checked twice (by the
// library's engine on the scene and by the tests' plain rules), the
// unsolvable ones proven so, --all counts against brute force, the same
// answer for any number of threads, limits, and the command line.
#include "orthoray/puzzle.hpp"
#include "orthoray/solve.hpp"
#include "support/lazor_levels.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

using namespace orthoray;
using namespace orthoray::test;

namespace {

bool all_true(const std::vector<bool>& v) {
    return std::find(v.begin(), v.end(), false) == v.end();
}

// The placed level keeps the level's fixed cells and puts exactly its
// blocks on open cells.
void check_uses_the_blocks(const LazorLevel& level, const LazorLevel& placed) {
    std::array<int, 3> used{};
    for (std::size_t i = 0; i < level.cells.size(); ++i) {
        if (level.cells[i] != LazorCell::open) {
            CHECK(placed.cells[i] == level.cells[i]);
            continue;
        }
        CHECK(placed.cells[i] != LazorCell::blocked);
        for (std::size_t k = 0; k < 3; ++k) used[k] += placed.cells[i] == lazor_blocks[k];
    }
    CHECK(used == level.blocks);
}

// The placements that light every point, by brute force and the plain rules.
long brute_force_count(const LazorLevel& level) {
    long count = 0;
    each_placement(
        level, [&](const LazorLevel& placed) { count += all_true(lazor_lit_by_rules(placed)); });
    return count;
}

} // namespace

TEST_CASE("every public level is solved, and each solution checks twice", "[puzzle][solve]") {
    const auto folder = lazor_folder_or_skip();
    if (!folder) return;
    int solved = 0;
    for (const auto& file : bff_files(*folder)) {
        INFO(file.string());
        const LazorLevel level = load_lazor_level(file.string());
        const LazorSolution s = solve_lazor(level);
        REQUIRE(s.status == LazorSolution::Status::solved);
        REQUIRE(s.placed);
        check_uses_the_blocks(level, *s.placed);
        CHECK(solve(lazor_scene(*s.placed)).yes());
        CHECK(all_true(lazor_lit_by_rules(*s.placed)));
        ++solved;
    }
    CHECK(solved == 165);
}

TEST_CASE("the unsolvable public levels are proven unsolvable", "[puzzle][solve]") {
    const auto folder = lazor_folder_or_skip();
    if (!folder) return;
    const auto files = bff_files(*folder / "unsolvable");
    CHECK(files.size() == 3);
    for (const auto& file : files) {
        INFO(file.string());
        const LazorLevel level = load_lazor_level(file.string());
        LazorSolveOptions options;
        options.all = true;
        const LazorSolution s = solve_lazor(level, options);
        CHECK(s.status == LazorSolution::Status::unsolvable);
        CHECK(s.solutions == "0");
        CHECK(brute_force_count(level) == 0);
        const CliResult r = run_cli("puzzle solve " + quote(file.string()));
        CHECK(r.status == 1);
        CHECK(r.out.find("answer       unsolvable\n") != std::string::npos);
    }
}

TEST_CASE("solution counts (--all) agree with brute force on small levels", "[puzzle][solve]") {
    const auto folder = lazor_folder_or_skip();
    if (!folder) return;
    // Levels with few placements, among them every kind of block, several
    // solutions (Kaelosonaa-dark_2: all 495; rbu1996-easy: 4 of 276), and
    // lasers that start beside blocks (numbered_4, tiny_5).
    const std::vector<std::string> names{
        "tiny_2",   "tiny_5",       "numbered_4",        "numbered_7",
        "tinier_7", "rbu1996-easy", "Kaelosonaa-dark_2", "tutorial_9",
        "dark_1",   "tiny_6"};
    for (const std::string& name : names) {
        INFO(name);
        const LazorLevel level = load_lazor_level((*folder / (name + ".bff")).string());
        for (const unsigned jobs : {1u, 3u}) {
            LazorSolveOptions options;
            options.all = true;
            options.jobs = jobs;
            const LazorSolution s = solve_lazor(level, options);
            CHECK(s.solutions == std::to_string(brute_force_count(level)));
        }
    }
}

TEST_CASE("the answer is the same for any number of threads", "[puzzle][solve]") {
    const auto folder = lazor_folder_or_skip();
    if (!folder) return;
    const auto files = bff_files(*folder);
    for (std::size_t i = 0; i < files.size(); i += 5) {
        INFO(files[i].string());
        const LazorLevel level = load_lazor_level(files[i].string());
        LazorSolveOptions one, many;
        many.jobs = 4;
        const LazorSolution a = solve_lazor(level, one), b = solve_lazor(level, many);
        REQUIRE(a.placed);
        REQUIRE(b.placed);
        CHECK(write_lazor_grid(*a.placed) == write_lazor_grid(*b.placed));
    }
}

TEST_CASE("a level with more blocks than open cells is unsolvable", "[puzzle][solve]") {
    // Built in code: the .bff reader refuses such a level. Every block must
    // be placed, and two blocks do not fit one open cell, even though the
    // laser never enters that cell and the point is lit without them.
    LazorLevel level;
    level.width = 2;
    level.height = 1;
    level.cells = {LazorCell::open, LazorCell::blocked};
    level.blocks = {2, 0, 0};
    LazorLaser laser;
    laser.x = 3;
    laser.y = 0;
    laser.dx = 1;
    laser.dy = 1;
    level.lasers = {laser};
    LazorPoint point;
    point.x = 4;
    point.y = 1;
    level.points = {point};
    CHECK(solve_lazor(level).status == LazorSolution::Status::unsolvable);
    // With one block it fits, and the point is lit wherever it goes.
    level.blocks = {1, 0, 0};
    CHECK(solve_lazor(level).status == LazorSolution::Status::solved);
}

TEST_CASE("limits stop the search with nothing claimed", "[puzzle][solve]") {
    const LazorLevel level =
        read_lazor_level("GRID START\no o o o\no o o o\no o o o\no o o o\nGRID STOP\nA 2\nC 1\n"
                         "L 2 7 1 -1\nP 3 0\nP 4 3\nP 2 5\nP 4 7\n"); // mad_1
    LazorSolveOptions options;
    options.max_nodes = 3;
    LazorSolution s = solve_lazor(level, options);
    CHECK(s.status == LazorSolution::Status::limit);
    CHECK(s.limit == "nodes");
    CHECK(!s.placed);
    // The count is one thread's, so never above the budget, whatever the
    // pieces searched beside the one that ran out (mad_1 needs 77 nodes).
    for (const std::uint64_t budget : {1, 10, 75, 76})
        for (const unsigned jobs : {1u, 4u}) {
            options.max_nodes = budget;
            options.jobs = jobs;
            s = solve_lazor(level, options);
            INFO("budget " << budget << ", " << jobs << " jobs");
            CHECK(s.status == LazorSolution::Status::limit);
            CHECK(s.nodes == budget);
        }

    const std::atomic<bool> stop{true};
    options = {};
    options.stop = &stop;
    s = solve_lazor(level, options);
    CHECK(s.status == LazorSolution::Status::limit);
    CHECK(s.limit == "stop");

    options = {};
    options.max_nodes = 1000000;
    s = solve_lazor(level, options);
    CHECK(s.status == LazorSolution::Status::solved);
}

TEST_CASE("puzzle solve and puzzle scene on the command line", "[puzzle][solve][cli]") {
    TempDir dir;
    const std::string level = dir.write(
        "mad_1.bff", "GRID START\no o o o\no o o o\no o o o\no o o o\nGRID STOP\nA 2\nC 1\n"
                     "L 2 7 1 -1\nP 3 0\nP 4 3\nP 2 5\nP 4 7\n");
    const std::string solved = dir.path("solved.bff");
    CliResult r = run_cli("puzzle solve " + quote(level) + " -o " + quote(solved));
    CHECK(r.status == 0);
    CHECK(r.out.rfind("GRID START\no o C o\no o o A\nA o o o\no o o o\nGRID STOP\n"
                      "point 1 (3, 0)  lit by laser 1 after 1 reflections\n"
                      "point 2 (4, 3)  lit by laser 1 after 2 reflections\n"
                      "point 3 (2, 5)  lit by laser 1 after 2 reflections\n"
                      "point 4 (4, 7)  lit by laser 1 after 3 reflections\n"
                      "answer       solved\n",
                      0) == 0);
    // The solved file is a level with every block fixed, and a placement.
    const LazorLevel again = load_lazor_level(solved);
    CHECK(again.blocks == std::array<int, 3>{0, 0, 0});
    const std::string scene = dir.path("solved.scene");
    r = run_cli("puzzle scene " + quote(level) + " --placement " + quote(solved) + " -o " +
                quote(scene));
    CHECK(r.status == 0);
    r = run_cli("solve " + quote(scene));
    CHECK(r.status == 0); // every target lit
    r = run_cli("puzzle scene " + quote(level));
    CHECK(r.status == 0);
    CHECK(r.out.rfind("dim 2\nray 3/2 1/2 1 1\n", 0) == 0);

    // --render: the solved level's branches, with its four points lit.
    const std::string picture = dir.path("solved.svg");
    r = run_cli("puzzle solve " + quote(level) + " --render " + quote(picture));
    CHECK(r.status == 0);
    std::ifstream svg_file(picture);
    const std::string svg((std::istreambuf_iterator<char>(svg_file)), {});
    CHECK(svg.find("<svg ") != std::string::npos);
    std::size_t lit = 0;
    for (std::size_t at = svg.find("<circle class=\"target-lit\""); at != std::string::npos;
         at = svg.find("<circle class=\"target-lit\"", at + 1))
        ++lit;
    CHECK(lit == 4);

    r = run_cli("puzzle solve --json --all --jobs 2 " + quote(level));
    CHECK(r.status == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j["answer"] == "solved");
    CHECK(j["solutions"] == 1);
    CHECK(j["grid"] == nlohmann::json::parse(R"(["o o C o","o o o A","A o o o","o o o o"])"));
    CHECK(j["jobs"] == 2);
    CHECK(j["points"][3] ==
          nlohmann::json::parse(R"({"point":4,"x":4,"y":7,"laser":1,"reflections":3})"));
    CHECK(r.out.find(R"("points":[{"point":1,"x":3,"y":0,"laser":1,"reflections":1},)") !=
          std::string::npos);

    r = run_cli("puzzle solve --max-nodes 2 " + quote(level));
    CHECK(r.status == 3);
    CHECK(r.out.find("answer       unknown\nreason       limit (--max-nodes reached)\n") !=
          std::string::npos);

    const std::string bad = dir.write("bad.bff", "GRID START\no o\nGRID STOP\nL 2 2 1 1\nP 1 0\n");
    r = run_cli("puzzle solve " + quote(bad));
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err == bad + ":4:3: found the laser at (2, 2), a block corner, expected the "
                         "midpoint of a cell edge (x + y odd)\n");
}

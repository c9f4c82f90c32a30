// The curated levels of instances/puzzles/ (written by `orthoray puzzle
// generate`, one changed by hand to be unsolvable): each solved with the
// answer and solution count of instances/puzzles/expected.json, each
// solution placed in the level's grid with exactly its blocks and checked
// again by `orthoray solve` on the scene `puzzle scene --placement` writes,
// by solve() in the library and by the tests' plain rules; where the
// placements are few enough, a brute-force count with the plain rules
// confirms the solver's, and every solution it finds is checked by solve().
#include "orthoray/puzzle.hpp"
#include "orthoray/solve.hpp"
#include "support/lazor_levels.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>

using namespace orthoray;
using namespace orthoray::test;

namespace {

bool all_true(const std::vector<bool>& v) {
    return std::find(v.begin(), v.end(), false) == v.end();
}

// The number of placements of the level's blocks on its open cells, or
// `cap` + 1 when there are more than `cap`.
long placements_up_to(const LazorLevel& level, long cap) {
    long cells =
        static_cast<long>(std::count(level.cells.begin(), level.cells.end(), LazorCell::open));
    long ways = 1;
    for (const int count : level.blocks)
        for (int i = 0; i < count; ++i, --cells) {
            ways = ways * cells / (i + 1); // C(cells, i + 1), built up exactly
            if (ways > cap) return cap + 1;
        }
    return ways;
}

} // namespace

TEST_CASE("the curated levels have their expected answers, each solution checked",
          "[puzzle][instances]") {
    const std::string folder = instance("puzzles");
    std::ifstream in(folder + "/expected.json");
    const nlohmann::json expected = nlohmann::json::parse(in);
    const auto files = bff_files(folder);
    CHECK(files.size() == expected.size());
    int solved = 0, unsolvable = 0, several = 0, brute_forced = 0;
    const TempDir dir;
    for (const auto& file : files) {
        const std::string name = file.filename().string();
        INFO(name);
        REQUIRE(expected.contains(name));
        const LazorLevel level = load_lazor_level(file.string());
        LazorSolveOptions options;
        options.all = true;
        const LazorSolution s = solve_lazor(level, options);
        const std::string answer = expected[name]["answer"];
        const long count = expected[name]["solutions"];
        CHECK(s.solutions == std::to_string(count));
        const CliResult cli = run_cli("puzzle solve " + quote(file.string()) + " -o " +
                                      quote(dir.path("solved.bff")));
        if (answer == "unsolvable") {
            CHECK(s.status == LazorSolution::Status::unsolvable);
            CHECK(cli.status == 1);
            ++unsolvable;
        } else {
            REQUIRE(s.status == LazorSolution::Status::solved);
            REQUIRE(cli.status == 0);
            // The solution the command line wrote: the level's grid with
            // exactly its blocks, lighting every point three ways.
            const LazorLevel placed =
                apply_lazor_placement(level, load_lazor_level(dir.path("solved.bff")), "solved");
            CHECK(write_lazor_grid(placed) == write_lazor_grid(*s.placed));
            CHECK(all_true(lazor_lit_by_rules(placed)));
            CHECK(solve(lazor_scene(placed)).yes());
            const CliResult scene =
                run_cli("puzzle scene " + quote(file.string()) + " --placement " +
                        quote(dir.path("solved.bff")) + " -o " + quote(dir.path("solved.scene")));
            CHECK(scene.status == 0);
            CHECK(run_cli("solve " + quote(dir.path("solved.scene"))).status == 0);
            ++solved;
            several += count > 1;
        }
        if (placements_up_to(level, 20'000) <= 20'000) {
            long found = 0;
            each_placement(level, [&](const LazorLevel& placed) {
                if (!all_true(lazor_lit_by_rules(placed))) return;
                ++found;
                CHECK(solve(lazor_scene(placed)).yes());
            });
            CHECK(found == count);
            ++brute_forced;
        }
    }
    CHECK(solved >= 10);
    CHECK(unsolvable >= 1);
    CHECK(several >= 1);
    CHECK(brute_forced >= 3);
}

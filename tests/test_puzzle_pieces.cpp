// The placement search in pieces (orthoray/puzzle_pieces.hpp, docs/puzzles.md
// "The search, in pieces"): on every public level, the pieces searched in
// any order and merged give what one search from the root gives (the first
// solution, the count, and for the generator's search the very node count
// and the same verdict at every budget around it); the texts sent between
// processes give the same search back; threads give the same outcome.
#include "orthoray/puzzle_pieces.hpp"
#include "puzzle/other_solution.hpp"
#include "puzzle/placement_search.hpp"
#include "support/case_count.hpp"
#include "support/lazor_levels.hpp"
#include "support/run_cli.hpp"

#include <catch2/catch.hpp>

using namespace orthoray;
using namespace orthoray::test;

namespace {

// Levels whose whole search stays under this many nodes, so the test stays
// within seconds (a quarter under sanitizers); the larger ones are covered
// by the command-line tests.
constexpr std::uint64_t whole_search_nodes = case_count(60'000);

// The public levels that read, from instances/puzzles and, when present,
// ../shared/puzzles/lazor.
std::vector<std::pair<std::string, LazorLevel>> public_levels() {
    std::vector<std::filesystem::path> files = bff_files(source_path("instances/puzzles"));
    if (const auto folder = lazor_folder_or_warn()) {
        const std::vector<std::filesystem::path> more = bff_files(*folder);
        files.insert(files.end(), more.begin(), more.end());
    }
    // Every one reads: the malformed samples are in a folder of their own,
    // which bff_files does not enter.
    std::vector<std::pair<std::string, LazorLevel>> out;
    for (const std::filesystem::path& file : files)
        out.emplace_back(file.filename().string(), load_lazor_level(file.string()));
    return out;
}

// Three quarters of the levels: the least of them each test below must
// compare. A level it does not compare is unsolved or not searched within
// the budget; a search grown slower would skip more of them. On 2026-12-01
// the tests compared 180 and 179 of 180 levels with the public ones, 15 and
// 14 of 15 with instances/puzzles alone.
int most_of(std::size_t levels) {
    return static_cast<int>(levels * 3 / 4);
}

// One search from the root, as the search was before it had pieces.
puzzle::SubtreeResult whole_search(const LazorLevel& level, bool all, std::uint64_t budget,
                                   const LazorLevel* other_than = nullptr) {
    std::uint64_t visited = 0;
    puzzle::PlacementSearch search(level, all, [&] { return visited++ >= budget; });
    if (other_than)
        search.skip_solutions([&](const puzzle::Board& leaf) {
            return puzzle::only_intended(level, *other_than, leaf);
        });
    return search.search({});
}

// Every piece, last first: the merge must not depend on the order.
std::vector<std::optional<LazorPieceResult>> backwards(const LazorSearchPieces& pieces) {
    std::vector<std::optional<LazorPieceResult>> results(pieces.size());
    for (std::size_t i = pieces.size(); i-- > 0;) results[i] = pieces.search(i);
    return results;
}

} // namespace

TEST_CASE("merged pieces give the whole search's first solution and count on every public level",
          "[puzzle][pieces][slow]") {
    const auto levels = public_levels();
    int compared = 0;
    for (const auto& [name, level] : levels) {
        const puzzle::SubtreeResult whole = whole_search(level, true, whole_search_nodes);
        if (!whole.complete) continue;
        CAPTURE(name);
        ++compared;
        const LazorSearchPieces all(level, true, std::nullopt);
        const std::optional<LazorSearchOutcome> counted = all.outcome(backwards(all));
        REQUIRE(counted);
        CHECK(counted->solutions == whole.solutions.get_str());
        CHECK(counted->first == (whole.first ? puzzle::board_text(*whole.first) : ""));
        CHECK(counted->nodes <= whole.nodes); // without the nodes above the split

        const LazorSearchPieces first(level, false, std::nullopt);
        const std::optional<LazorSearchOutcome> found = first.outcome(backwards(first));
        REQUIRE(found);
        CHECK(found->first == counted->first);
        CHECK((found->status == LazorSearchOutcome::Status::found) == whole.first.has_value());
        // Threads merge to the same outcome, nodes included.
        const std::optional<LazorSearchOutcome> threaded =
            first.outcome(run_lazor_pieces(first, 2));
        REQUIRE(threaded);
        CHECK(threaded->first == found->first);
        CHECK(threaded->nodes == found->nodes);
    }
    CHECK(compared >= most_of(levels.size()));
}

TEST_CASE("the generator's search in pieces counts nodes as the search from the root did",
          "[puzzle][pieces][generate][slow]") {
    const auto levels = public_levels();
    int compared = 0;
    for (const auto& [name, level] : levels) {
        const LazorSolution solved = solve_lazor(level);
        if (solved.status != LazorSolution::Status::solved) continue;
        const LazorLevel& intended = *solved.placed;
        const puzzle::SubtreeResult whole =
            whole_search(level, false, whole_search_nodes, &intended);
        if (!whole.complete) continue;
        CAPTURE(name);
        ++compared;
        // At the budget the search needs, one less, and less still, the
        // verdict, the leaf and the nodes are the one-pass search's.
        for (const std::uint64_t budget :
             {whole.nodes, whole.nodes - 1, whole.nodes / 2, std::uint64_t{1}}) {
            CAPTURE(budget);
            const puzzle::SubtreeResult reference = whole_search(level, false, budget, &intended);
            const puzzle::OtherSolution other =
                puzzle::find_other_solution(level, intended, budget, nullptr);
            if (reference.first) {
                REQUIRE(other.status == puzzle::OtherSolution::Status::found);
                CHECK(puzzle::board_text(other.leaf) == puzzle::board_text(*reference.first));
                CHECK(other.nodes == reference.nodes);
            } else if (reference.complete) {
                CHECK(other.status == puzzle::OtherSolution::Status::none);
                CHECK(other.nodes == reference.nodes);
            } else {
                CHECK(other.status == puzzle::OtherSolution::Status::limit);
            }
        }
    }
    CHECK(compared >= most_of(levels.size()));
}

TEST_CASE("a search and its piece results survive their texts", "[puzzle][pieces]") {
    const auto levels = public_levels();
    int compared = 0;
    for (const auto& [name, level] : levels) {
        if (compared == 40) break;
        ++compared;
        CAPTURE(name);
        const LazorSearchPieces pieces(level, true, 5000);
        const LazorSearchPieces again = LazorSearchPieces::from_text(pieces.to_text());
        REQUIRE(again.size() == pieces.size());
        CHECK(again.to_text() == pieces.to_text());
        for (std::size_t i = 0; i < pieces.size(); i += 7) {
            const LazorPieceResult r = pieces.search(i);
            CHECK(lazor_piece_text(again.search(i)) == lazor_piece_text(r));
            CHECK(lazor_piece_text(lazor_piece_from_text(lazor_piece_text(r))) ==
                  lazor_piece_text(r));
        }
    }
    CHECK(compared >= 15); // instances/puzzles alone has 15 levels
    // A leaf of the largest grid (64 x 64 cells) in one piece of text.
    LazorPieceResult big;
    big.end = LazorPieceResult::End::complete;
    big.nodes = 123456789012;
    big.solutions = "98765432109876543210987654321";
    big.first = std::string(64 * 64, '4') + "/1/0/2/4000";
    CHECK(lazor_piece_text(lazor_piece_from_text(lazor_piece_text(big))) == lazor_piece_text(big));
    CHECK(lazor_piece_from_text(lazor_piece_text(big)).first == big.first);
    // The generator's search carries its intended placement along.
    const LazorLevel level = load_lazor_level(source_path("instances/puzzles/reflect-7x7.bff"));
    const LazorLevel intended = *solve_lazor(level).placed;
    const LazorSearchPieces other = LazorSearchPieces::other_than(level, intended, 1000);
    CHECK(LazorSearchPieces::from_text(other.to_text()).to_text() == other.to_text());
}

// solve_lazor(): the placement search in pieces (orthoray/puzzle_pieces.hpp,
// docs/puzzles.md, "The search"), on threads or whatever runner the caller
// gives. The answer is the first solution of the first piece that has one,
// merged in search order, so it does not depend on who finished first.
#include "orthoray/puzzle.hpp"
#include "orthoray/puzzle_pieces.hpp"
#include "orthoray/solve.hpp"

#include "puzzle/placement_search.hpp"

#include <stdexcept>

namespace orthoray {
namespace {

using puzzle::Board;

// The level with the blocks of a solution leaf: the decided cells as they
// are, and the blocks left on the undecided cells in row-major order,
// reflect blocks first, then opaque, then refract (any arrangement lights
// the same points, since no branch enters those cells).
LazorLevel placement_of(const LazorLevel& level, Board board) {
    LazorLevel placed = level;
    for (std::size_t i = 0; i < board.cells.size(); ++i) {
        puzzle::Content c = board.cells[i];
        if (c == puzzle::undecided) {
            c = puzzle::empty;
            for (int k = 0; k < 3; ++k)
                if (board.remaining[k] > 0) {
                    --board.remaining[k];
                    c = static_cast<puzzle::Content>(k + 1);
                    break;
                }
        }
        if (level.cells[i] == LazorCell::open)
            placed.cells[i] = c == puzzle::empty ? LazorCell::open : lazor_blocks[c - 1];
    }
    placed.blocks = {};
    return placed;
}

// The solution once more, by the library's own illumination engine on the
// translated scene: a disagreement is a bug, not an answer. Returns what
// the engine says of each point.
std::vector<TargetAnswer> recheck(const LazorLevel& placed) {
    const Answer answer = solve(lazor_scene(placed));
    if (!answer.yes())
        throw std::logic_error("the placement search found a placement that solve() says "
                               "leaves a point unlit");
    if (answer.illumination()) return answer.targets;
    // One laser, one point, no splitter: a single trajectory that hits.
    TargetAnswer hit;
    hit.status = TargetAnswer::Status::lit;
    hit.reflections = answer.reflections;
    hit.ray = 1;
    return {hit};
}

} // namespace

LazorSolution solve_lazor(const LazorLevel& level, const LazorSolveOptions& options) {
    const LazorSearchPieces pieces(level, options.all, options.max_nodes);
    const std::vector<std::optional<LazorPieceResult>> results =
        options.runner ? (*options.runner)(pieces)
                       : run_lazor_pieces(pieces, options.jobs, options.stop, options.progress);
    LazorSolution solution;
    std::optional<LazorSearchOutcome> outcome = pieces.outcome(results);
    if (!outcome) { // the runner was stopped before the pieces that decide
        outcome.emplace();
        outcome->limit = "stop";
        for (const std::optional<LazorPieceResult>& r : results)
            if (r) outcome->nodes += r->nodes;
    }
    solution.nodes = outcome->nodes;
    switch (outcome->status) {
    case LazorSearchOutcome::Status::limit:
        solution.status = LazorSolution::Status::limit;
        solution.limit = outcome->limit;
        return solution;
    case LazorSearchOutcome::Status::none:
        solution.solutions = outcome->solutions;
        solution.status = LazorSolution::Status::unsolvable;
        return solution;
    case LazorSearchOutcome::Status::found:
        break;
    }
    solution.solutions = outcome->solutions;
    solution.placed = placement_of(level, puzzle::board_from_text(outcome->first));
    solution.points = recheck(*solution.placed);
    solution.status = LazorSolution::Status::solved;
    return solution;
}

} // namespace orthoray

#include "puzzle/other_solution.hpp"

namespace orthoray::puzzle {

bool only_intended(const LazorLevel& level, const LazorLevel& intended, const Board& leaf) {
    if (arrangements(leaf) != 1) return false;
    Content filler = empty;
    for (int k = 0; k < 3; ++k)
        if (leaf.remaining[k] > 0) filler = static_cast<Content>(k + 1);
    for (std::size_t i = 0; i < leaf.cells.size(); ++i) {
        if (level.cells[i] != LazorCell::open) continue;
        const Content placed = leaf.cells[i] == undecided ? filler : leaf.cells[i];
        const Content wanted =
            intended.cells[i] == LazorCell::open ? empty : content_of(intended.cells[i]);
        if (placed != wanted) return false;
    }
    return true;
}

OtherSolution find_other_solution(const LazorLevel& level, const LazorLevel& intended,
                                  std::uint64_t max_nodes, const LazorPieceRunner* runner) {
    const LazorSearchPieces pieces = LazorSearchPieces::other_than(level, intended, max_nodes);
    const std::vector<std::optional<LazorPieceResult>> results =
        runner ? (*runner)(pieces) : run_lazor_pieces(pieces, 1);
    const std::optional<LazorSearchOutcome> outcome = pieces.outcome(results);
    OtherSolution out;
    if (!outcome) return out; // the runner was stopped: a limit
    out.nodes = outcome->nodes;
    switch (outcome->status) {
    case LazorSearchOutcome::Status::found:
        out.status = OtherSolution::Status::found;
        out.leaf = board_from_text(outcome->first);
        break;
    case LazorSearchOutcome::Status::none:
        out.status = OtherSolution::Status::none;
        break;
    case LazorSearchOutcome::Status::limit:
        break;
    }
    return out;
}

} // namespace orthoray::puzzle

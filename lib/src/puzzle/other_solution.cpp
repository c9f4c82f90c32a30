#include "puzzle/other_solution.hpp"

namespace orthoray::puzzle {
namespace {

// Whether the leaf's placements are `intended` and nothing else: one
// arrangement of the blocks left (none left, or one kind filling every
// undecided cell), which agrees with `intended` on every open cell.
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

} // namespace

OtherSolution find_other_solution(const LazorLevel& level, const LazorLevel& intended,
                                  std::uint64_t max_nodes) {
    std::uint64_t visited = 0;
    PlacementSearch search(level, false, [&] { return visited++ >= max_nodes; });
    search.skip_solutions([&](const Board& leaf) { return only_intended(level, intended, leaf); });
    SubtreeResult result = search.search({});
    OtherSolution out;
    out.nodes = result.nodes;
    if (result.first) {
        out.status = OtherSolution::Status::found;
        out.leaf = std::move(*result.first);
    } else {
        out.status = result.complete ? OtherSolution::Status::none : OtherSolution::Status::limit;
    }
    return out;
}

} // namespace orthoray::puzzle

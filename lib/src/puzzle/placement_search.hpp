// The placement search of docs/puzzles.md, one subtree at a time: a node
// fixes some open cells (a block, or empty for good); its children decide the
// first undecided cell that a laser branch enters, in the order reflect,
// opaque, refract, empty. A node where no branch enters an undecided cell,
// or where no block is left to place, is a leaf: the beams can no longer
// change, and the blocks left go on the undecided cells in any arrangement.
#pragma once

#include "orthoray/number.hpp"
#include "puzzle/beam_walk.hpp"

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace orthoray::puzzle {

struct Decision {
    int cell;
    Content content;
};

// A node: the contents of every cell and the blocks still to place.
struct Board {
    std::vector<Content> cells;
    std::array<int, 3> remaining{}; // reflect, opaque, refract
    int undecided_cells = 0;        // open cells not decided yet

    int remaining_total() const { return remaining[0] + remaining[1] + remaining[2]; }
    void apply(const Decision& d);
    void undo(const Decision& d);
};

Board initial_board(const LazorLevel& level);

// What one subtree holds.
struct SubtreeResult {
    bool complete = false;      // searched to the end (not stopped)
    std::optional<Board> first; // its first solution leaf in search order
    Integer solutions;          // with count_all: the placements at its solution leaves
    std::uint64_t nodes = 0;
};

class PlacementSearch {
public:
    // `stop` is asked at every node; when it says true the search unwinds.
    PlacementSearch(const LazorLevel& level, bool count_all, std::function<bool()> stop);

    // The children of the node reached by `path` from the root, in search
    // order (empty for a leaf or a pruned node).
    std::vector<Decision> children(const std::vector<Decision>& path);

    // Searches the subtree below `path`: to its first solution, or with
    // count_all to its end.
    SubtreeResult search(const std::vector<Decision>& path);

    // Solution leaves for which `skip` says true are passed over as if they
    // lit nothing (the generator looks for a solution other than its own).
    void skip_solutions(std::function<bool(const Board&)> skip) { skip_ = std::move(skip); }

private:
    struct Branches {
        std::array<Decision, 4> decisions;
        int count = 0;
        bool solution = false; // a leaf whose beams light every point
    };
    // Walks the current node: its branches in search order (none for a leaf
    // or a node the reachability bound prunes).
    Branches expand();
    void explore();

    const LazorLevel& level_;
    bool count_all_;
    std::function<bool()> stop_;
    std::function<bool(const Board&)> skip_;
    BeamWalk walk_;
    Board board_;
    SubtreeResult result_;
    bool stopped_ = false;
};

// The number of ways to put the blocks left on the undecided cells.
Integer arrangements(const Board& board);

// A board as text without spaces (one digit a cell, then the blocks left),
// for a piece's result sent to another process, and back.
std::string board_text(const Board& board);
Board board_from_text(std::string_view text);

} // namespace orthoray::puzzle

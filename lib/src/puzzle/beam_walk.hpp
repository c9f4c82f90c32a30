// Walking a level's laser branches on its small integer grid, for the
// placement search (docs/puzzles.md, "The search"). A laser moves one unit
// diagonally at a time, from the midpoint of a cell edge to the next; only
// there can it meet an element. What happens at such a point depends only on
// the two cells beside the edge and the direction, so the walk looks it up in
// a table of 4 x 4 x 2 x 4 outcomes that the library's acting rule
// (engine::event_outcome, on the elements of block_edges.hpp) fills once:
// the walk decides nothing by itself.
#pragma once

#include "orthoray/puzzle.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace orthoray::puzzle {

// What a cell holds during the search: nothing (open and decided empty,
// blocked, or outside the grid), a block, or not decided yet.
enum Content : std::uint8_t { empty = 0, reflect = 1, opaque = 2, refract = 3, undecided = 4 };

Content content_of(LazorCell cell);

// Directions are numbered by their signs in file coordinates:
// bit 0 set when dx > 0, bit 1 set when dy > 0.
constexpr int direction_index(int dx, int dy) {
    return (dx > 0 ? 1 : 0) | (dy > 0 ? 2 : 0);
}

struct EdgeOutcome {
    bool absorbed = false;
    std::uint8_t directions = 0; // bit d: direction d leaves the point
};

// The acting rule at an edge midpoint: `vertical` for an edge x = const, the
// contents of the cell before the edge (smaller coordinate across it) and
// after it, and the arriving direction.
class ActingTable {
public:
    static const ActingTable& get();
    const EdgeOutcome& at(bool vertical, Content low, Content high, int direction) const {
        return table_[vertical][low][high][direction];
    }

private:
    ActingTable();
    EdgeOutcome table_[2][4][4][4];
};

class BeamWalk {
public:
    explicit BeamWalk(const LazorLevel& level);

    // Walks every branch of every laser over `cells` (width * height
    // contents), treating undecided cells as empty. Returns the first
    // undecided cell a branch enters, in walk order, or -1 when none is.
    int walk(const std::vector<Content>& cells);
    // Whether the last walk passed every point.
    bool all_lit() const;

    // An over-approximation for pruning: may some completion light every
    // point? At an undecided cell a branch may do what any block in
    // `can_place` (bit k for content k) or an empty cell would do.
    bool may_light_all(const std::vector<Content>& cells, unsigned can_place);

    // The points the last walk passed, in file order.
    std::vector<bool> lit_points() const;

private:
    template <bool Relaxed>
    int run(const std::vector<Content>& cells, unsigned can_place);

    // A laser's first state, the cell behind it (-1 outside the grid) and
    // the direction a branch sent back into that cell would take.
    struct Start {
        int state, behind, back;
    };

    int width_, height_, columns_; // columns_ = 2 * width + 1 edge positions a row
    std::vector<Start> starts_;
    std::vector<int> points_; // position index of each point
    std::vector<std::uint32_t> state_seen_, position_seen_;
    std::uint32_t stamp_ = 0;
    std::vector<int> stack_;
    const ActingTable& table_;
};

} // namespace orthoray::puzzle

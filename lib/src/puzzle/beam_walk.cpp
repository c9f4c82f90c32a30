#include "puzzle/beam_walk.hpp"

#include "engine/event_rule.hpp"
#include "puzzle/block_edges.hpp"

namespace orthoray::puzzle {
namespace {

constexpr LazorCell block_of[4] = {LazorCell::open, LazorCell::reflect, LazorCell::opaque,
                                   LazorCell::refract};

// The outcome at the midpoint of the edge between two cells, from the
// scene's own elements: both cells' blocks are built where lazor_scene()
// puts them, the elements through the point that act on the ray are
// gathered as the engines gather them, and event_outcome() decides.
EdgeOutcome decide(bool vertical, Content low, Content high, int direction) {
    // Vertical: cells (0, 0) and (1, 0) of a 2 x 1 grid meet at x = 2, the
    // point (2, 1). Horizontal: cells (0, 0) and (0, 1) of a 1 x 2 grid
    // meet at y = 2, the point (1, 2).
    const int height = vertical ? 1 : 2;
    const int dx = direction & 1 ? 1 : -1, dy = direction & 2 ? 1 : -1;
    const Vector q = vertical ? scene_point(2, 1, height) : scene_point(1, 2, height);
    const Vector v = scene_direction(dx, dy);
    std::vector<Element> elements;
    const Content contents[2] = {low, high};
    for (int side = 0; side < 2; ++side) {
        if (contents[side] == empty) continue;
        const int column = vertical ? side : 0, row = vertical ? 0 : side;
        for (Element& e : block_edges(block_of[contents[side]], column, row, height))
            elements.push_back(std::move(e));
    }
    std::vector<const Element*> acting;
    for (const Element& e : elements) {
        bool on = true;
        for (int j = 0; j < 2; ++j) on = on && e.lo[j] <= q[j] && q[j] <= e.hi[j];
        if (on && engine::acts_on(e, v)) acting.push_back(&e);
    }
    const engine::EventOutcome event = engine::event_outcome(2, acting, v);
    EdgeOutcome out;
    out.absorbed = event.absorbed;
    for (const engine::Outgoing& o : event.outgoing)
        out.directions |= static_cast<std::uint8_t>(
            1u << direction_index(sgn(o.direction[0]), -sgn(o.direction[1])));
    return out;
}

} // namespace

Content content_of(LazorCell cell) {
    switch (cell) {
    case LazorCell::reflect:
        return reflect;
    case LazorCell::opaque:
        return opaque;
    case LazorCell::refract:
        return refract;
    case LazorCell::open:
        return undecided;
    case LazorCell::blocked:
        return empty;
    }
    return empty;
}

ActingTable::ActingTable() {
    for (int vertical = 0; vertical < 2; ++vertical)
        for (int low = 0; low < 4; ++low)
            for (int high = 0; high < 4; ++high)
                for (int d = 0; d < 4; ++d)
                    table_[vertical][low][high][d] = decide(
                        vertical != 0, static_cast<Content>(low), static_cast<Content>(high), d);
}

const ActingTable& ActingTable::get() {
    static const ActingTable table;
    return table;
}

BeamWalk::BeamWalk(const LazorLevel& level)
    : width_(level.width), height_(level.height), columns_(2 * level.width + 1),
      table_(ActingTable::get()) {
    const std::size_t positions = static_cast<std::size_t>(columns_) * (2 * height_ + 1);
    state_seen_.assign(4 * positions, 0);
    position_seen_.assign(positions, 0);
    for (const LazorLaser& l : level.lasers) {
        // The block ahead sends a branch back across the start edge by
        // negating the component across it.
        const bool vertical = l.x % 2 == 0;
        starts_.push_back(Start{(l.y * columns_ + l.x) * 4 + direction_index(l.dx, l.dy),
                                cell_behind(level, l),
                                direction_index(vertical ? -l.dx : l.dx, vertical ? l.dy : -l.dy)});
    }
    for (const LazorPoint& p : level.points) points_.push_back(p.y * columns_ + p.x);
}

template <bool Relaxed>
int BeamWalk::run(const std::vector<Content>& cells, unsigned can_place) {
    if (++stamp_ == 0) { // the stamps wrapped: start the marks afresh
        std::fill(state_seen_.begin(), state_seen_.end(), 0);
        std::fill(position_seen_.begin(), position_seen_.end(), 0);
        stamp_ = 1;
    }
    int first_undecided = -1;
    auto cell_at = [&](int column, int row) {
        return column >= 0 && column < width_ && row >= 0 && row < height_ ? row * width_ + column
                                                                           : -1;
    };
    // One state: the acting table at its edge point, then the next states.
    auto step = [&](int state, const Start* start) {
        const int position = state >> 2, d = state & 3;
        const int x = position % columns_, y = position / columns_;
        position_seen_[position] = stamp_;
        // The cells before and after the edge through (x, y), and which of
        // the two the branch enters.
        const bool vertical = x % 2 == 0;
        const int low =
            vertical ? cell_at(x / 2 - 1, (y - 1) / 2) : cell_at((x - 1) / 2, y / 2 - 1);
        const int high = vertical ? cell_at(x / 2, (y - 1) / 2) : cell_at((x - 1) / 2, y / 2);
        const bool enters_high = vertical ? (d & 1) != 0 : (d & 2) != 0;
        const int entered = enters_high ? high : low, left = enters_high ? low : high;
        // A block on the cell being left never acts (its edges face
        // outward; the tests check the table agrees), so an undecided cell
        // there counts as empty.
        const Content left_content = left < 0 || cells[left] == undecided ? empty : cells[left];
        Content entered_content = entered < 0 ? empty : cells[entered];
        auto outcome = [&](Content in) {
            return table_
                .at(vertical, enters_high ? left_content : in, enters_high ? in : left_content, d)
                .directions;
        };
        std::uint8_t directions = 0;
        if (entered_content != undecided) {
            directions = outcome(entered_content);
        } else if constexpr (Relaxed) {
            // Whatever may still be placed there, or nothing.
            for (unsigned k = 0; k < 4; ++k)
                if (k == empty || (can_place & (1u << k)))
                    directions |= outcome(static_cast<Content>(k));
        } else {
            if (first_undecided < 0) first_undecided = entered;
            directions = outcome(empty);
        }
        // At a laser's start, a branch sent back into a reflect or opaque
        // block behind it ends (docs/puzzles.md); sent back into an
        // undecided cell, it enters that cell.
        if (start && start->behind >= 0 && (directions & (1u << start->back))) {
            const Content behind = cells[start->behind];
            if (behind == reflect || behind == opaque)
                directions &= static_cast<std::uint8_t>(~(1u << start->back));
            else if (!Relaxed && behind == undecided && first_undecided < 0)
                first_undecided = start->behind;
        }
        for (int next = 3; next >= 0; --next) {
            if (!(directions & (1u << next))) continue;
            const int nx = x + (next & 1 ? 1 : -1), ny = y + (next & 2 ? 1 : -1);
            if (nx < 0 || nx >= columns_ || ny < 0 || ny > 2 * height_) continue; // leaves
            const int to = (ny * columns_ + nx) * 4 + next;
            if (state_seen_[to] == stamp_) continue;
            state_seen_[to] = stamp_;
            stack_.push_back(to);
        }
    };
    for (const Start& start : starts_) {
        if (state_seen_[start.state] == stamp_) continue;
        state_seen_[start.state] = stamp_;
        step(start.state, &start);
        while (!stack_.empty()) {
            const int state = stack_.back();
            stack_.pop_back();
            step(state, nullptr);
        }
    }
    return first_undecided;
}

int BeamWalk::walk(const std::vector<Content>& cells) {
    return run<false>(cells, 0);
}

bool BeamWalk::all_lit() const {
    for (const int p : points_)
        if (position_seen_[p] != stamp_) return false;
    return true;
}

bool BeamWalk::may_light_all(const std::vector<Content>& cells, unsigned can_place) {
    run<true>(cells, can_place);
    return all_lit();
}

std::vector<bool> BeamWalk::lit_points() const {
    std::vector<bool> lit;
    for (const int p : points_) lit.push_back(position_seen_[p] == stamp_);
    return lit;
}

} // namespace orthoray::puzzle

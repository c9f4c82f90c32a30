// Generating levels (docs/puzzles.md, "Generation"): a random grid, lasers
// entering from its sides, the blocks placed one by one where the lasers
// go, points that need every block, then points (or closed cells) that rule
// out every other placement the search finds; the solver's --all count
// decides whether the level is kept, and its nodes measure the difficulty. Every draw goes
// through orthoray::uniform, so a seed gives the same level everywhere.
#include "orthoray/generate.hpp"
#include "orthoray/puzzle.hpp"

#include "puzzle/beam_walk.hpp"
#include "puzzle/other_solution.hpp"

#include <algorithm>
#include <limits>
#include <random>

namespace orthoray {
namespace {

int draw(std::mt19937_64& rng, int lo, int hi) {
    return static_cast<int>(uniform(rng, lo, hi));
}

template <class T>
void shuffle(std::vector<T>& items, std::mt19937_64& rng) {
    for (std::size_t i = items.size(); i > 1; --i)
        std::swap(
            items[i - 1],
            items[static_cast<std::size_t>(uniform(rng, 0, static_cast<std::int64_t>(i) - 1))]);
}

// A laser on a random side of the grid, moving into it.
LazorLaser side_laser(std::mt19937_64& rng, int width, int height) {
    LazorLaser l;
    const int side = draw(rng, 0, 3);
    if (side < 2) { // top or bottom
        l.x = 2 * draw(rng, 0, width - 1) + 1;
        l.y = side == 0 ? 0 : 2 * height;
        l.dx = draw(rng, 0, 1) ? 1 : -1;
        l.dy = side == 0 ? 1 : -1;
    } else { // left or right
        l.x = side == 2 ? 0 : 2 * width;
        l.y = 2 * draw(rng, 0, height - 1) + 1;
        l.dx = side == 2 ? 1 : -1;
        l.dy = draw(rng, 0, 1) ? 1 : -1;
    }
    return l;
}

// Every edge midpoint of the grid (x + y odd), row by row.
std::vector<LazorPoint> midpoints(const LazorLevel& level) {
    std::vector<LazorPoint> out;
    for (int y = 0; y <= 2 * level.height; ++y)
        for (int x = 0; x <= 2 * level.width; ++x)
            if ((x + y) % 2 == 1) out.push_back(LazorPoint{x, y, 0});
    return out;
}

// The search's contents of a placed level: open cells empty.
std::vector<puzzle::Content> contents(const LazorLevel& placed) {
    std::vector<puzzle::Content> cells;
    for (const LazorCell c : placed.cells)
        cells.push_back(c == LazorCell::open ? puzzle::empty : puzzle::content_of(c));
    return cells;
}

// Places the blocks one at a time on cells the lasers enter, as a random
// descent of the solver's search tree: at each step the first open cell the
// lasers enter gets the next block (two chances in three) or is passed
// over; a block after which the lasers would enter no open cell while
// blocks are left (a reflect block on a laser's first cell sends it
// straight out) is passed over instead. A block placed downstream never
// moves the lasers upstream, so every block ends on a laser's path. False
// when the lasers run out of open cells first.
bool place_on_paths(LazorLevel& placed, std::vector<LazorCell> kinds, std::mt19937_64& rng) {
    std::vector<puzzle::Content> cells;
    for (const LazorCell c : placed.cells) cells.push_back(puzzle::content_of(c));
    puzzle::BeamWalk walk(placed);
    for (int cell = walk.walk(cells); cell >= 0 && !kinds.empty();) {
        if (draw(rng, 0, 2) != 0) {
            cells[cell] = puzzle::content_of(kinds.back());
            const int next = walk.walk(cells);
            if (next >= 0 || kinds.size() == 1) {
                placed.cells[cell] = kinds.back();
                kinds.pop_back();
                cell = next;
                continue;
            }
        }
        cells[cell] = puzzle::empty; // passed over
        cell = walk.walk(cells);
    }
    return kinds.empty();
}

// One attempt's choice of points for the placement drawn (`placed`).
class PointChooser {
public:
    PointChooser(const LazorLevel& placed, int count, std::mt19937_64& rng)
        : count_(count), rng_(rng), all_(midpoints(placed)), probe_(with_points(placed, all_)) {
        probe_.walk(contents(placed));
        lit_ = probe_.lit_points();
        for (std::size_t i = 0; i < all_.size(); ++i)
            for (const LazorLaser& l : placed.lasers)
                if (all_[i].x == l.x && all_[i].y == l.y) lit_[i] = false;
        witnesses_.resize(all_.size());
        for (std::size_t b = 0; b < placed.cells.size(); ++b) {
            if (placed.cells[b] != LazorCell::reflect && placed.cells[b] != LazorCell::refract)
                continue;
            LazorLevel without = placed;
            without.cells[b] = LazorCell::open;
            probe_.walk(contents(without));
            const std::vector<bool> still = probe_.lit_points();
            for (std::size_t i = 0; i < all_.size(); ++i)
                if (lit_[i] && !still[i]) witnesses_[i].push_back(blocks_);
            ++blocks_;
        }
    }

    // Greedily, points whose darkness would show that a reflect or refract
    // block was left out, each chosen to witness as many blocks not yet
    // witnessed as possible. Opaque blocks only take light away, so no point
    // witnesses them. False when `count` points cannot do it.
    bool witness_blocks() {
        std::vector<bool> witnessed(static_cast<std::size_t>(blocks_), false);
        for (int left = blocks_; left > 0;) {
            std::vector<std::size_t> best;
            int most = 0;
            for (std::size_t i = 0; i < all_.size(); ++i) {
                int gain = 0;
                for (const int b : witnesses_[i]) gain += witnessed[b] ? 0 : 1;
                if (gain > most) best.clear(), most = gain;
                if (gain == most && gain > 0) best.push_back(i);
            }
            if (most == 0 || full()) return false;
            const std::size_t pick = pick_one(best);
            chosen_.push_back(pick);
            for (const int b : witnesses_[pick]) {
                left -= witnessed[b] ? 0 : 1;
                witnessed[b] = true;
            }
        }
        return true;
    }

    // A point the placement drawn lights and the `other` leaf's lasers do
    // not (open cells of `other` undecided count as empty); false when the
    // points are all taken or no such point exists.
    bool add_point_against(const std::vector<puzzle::Content>& other) {
        probe_.walk(other);
        const std::vector<bool> lit_other = probe_.lit_points();
        std::vector<std::size_t> apart;
        for (std::size_t i = 0; i < all_.size(); ++i)
            if (lit_[i] && !lit_other[i] && !taken(i)) apart.push_back(i);
        if (apart.empty() || full()) return false;
        chosen_.push_back(pick_one(apart));
        return true;
    }

    // Adds the lit points that depend on the most blocks (ties in random
    // order) until there are `total`; false when the lasers pass too few.
    bool fill_to(int total) {
        std::vector<std::size_t> rest;
        for (std::size_t i = 0; i < all_.size(); ++i)
            if (lit_[i] && !taken(i)) rest.push_back(i);
        shuffle(rest, rng_);
        std::stable_sort(rest.begin(), rest.end(), [&](std::size_t a, std::size_t b) {
            return witnesses_[a].size() > witnesses_[b].size();
        });
        for (std::size_t i = 0; static_cast<int>(chosen_.size()) < total; ++i) {
            if (i == rest.size()) return false;
            chosen_.push_back(rest[i]);
        }
        return true;
    }

    // The points chosen so far, in row-major order.
    std::vector<LazorPoint> chosen() const {
        std::vector<std::size_t> points = chosen_;
        std::sort(points.begin(), points.end());
        std::vector<LazorPoint> out;
        for (const std::size_t i : points) out.push_back(all_[i]);
        return out;
    }

private:
    static LazorLevel with_points(LazorLevel level, const std::vector<LazorPoint>& points) {
        level.points = points;
        return level;
    }
    bool full() const { return static_cast<int>(chosen_.size()) >= count_; }
    bool taken(std::size_t i) const {
        return std::find(chosen_.begin(), chosen_.end(), i) != chosen_.end();
    }
    std::size_t pick_one(const std::vector<std::size_t>& from) {
        return from[static_cast<std::size_t>(
            uniform(rng_, 0, static_cast<std::int64_t>(from.size()) - 1))];
    }

    int count_;
    std::mt19937_64& rng_;
    std::vector<LazorPoint> all_;
    puzzle::BeamWalk probe_;
    std::vector<bool> lit_;                   // passed by the placement drawn
    std::vector<std::vector<int>> witnesses_; // the blocks whose removal darkens each point
    int blocks_ = 0;                          // reflect and refract blocks placed
    std::vector<std::size_t> chosen_;
};

// The open cells some branch of `placed` enters: the walk names the first
// undecided cell a branch enters, and undecided cells count as empty, so
// marking each open cell undecided until none is entered finds them all.
std::vector<bool> entered_cells(const LazorLevel& placed) {
    std::vector<puzzle::Content> cells = contents(placed);
    for (std::size_t i = 0; i < cells.size(); ++i)
        if (placed.cells[i] == LazorCell::open) cells[i] = puzzle::undecided;
    std::vector<bool> entered(cells.size(), false);
    puzzle::BeamWalk walk(placed);
    for (int cell; (cell = walk.walk(cells)) >= 0;) {
        entered[static_cast<std::size_t>(cell)] = true;
        cells[static_cast<std::size_t>(cell)] = puzzle::empty;
    }
    return entered;
}

// At most this share of a level's cells may be closed ('x'): a level
// closed down to its lasers' paths would show its solution.
constexpr int closed_share_percent = 50;

// Makes the placement drawn the level's only solution: while the search
// finds another, adds a point that tells them apart, or, when the other
// lights every point the drawn one does, closes ('x') the cells where the
// other puts a block (or may put one it has left over) and the drawn
// placement's lasers never go, which changes nothing for the drawn
// placement. False when neither can be done, the points run out, the closed
// cells would pass their share, or a search reaches `max_nodes`.
bool cut_other_solutions(LazorLevel& level, LazorLevel& placed, PointChooser& points,
                         std::uint64_t max_nodes, const LazorPieceRunner* runner) {
    const std::vector<bool> entered = entered_cells(placed);
    const std::size_t most_closed = level.cells.size() * closed_share_percent / 100;
    while (true) {
        level.points = placed.points = points.chosen();
        const puzzle::OtherSolution other =
            puzzle::find_other_solution(level, placed, max_nodes, runner);
        if (other.status == puzzle::OtherSolution::Status::none) return true;
        if (other.status == puzzle::OtherSolution::Status::limit) return false;
        if (points.add_point_against(other.leaf.cells)) continue;
        std::vector<std::size_t> to_close;
        for (std::size_t i = 0; i < level.cells.size(); ++i) {
            const puzzle::Content c = other.leaf.cells[i];
            const bool block =
                c == puzzle::undecided ? other.leaf.remaining_total() > 0 : c != puzzle::empty;
            if (placed.cells[i] == LazorCell::open && !entered[i] && block) to_close.push_back(i);
        }
        const auto closed = static_cast<std::size_t>(
            std::count(level.cells.begin(), level.cells.end(), LazorCell::blocked));
        if (to_close.empty() || closed + to_close.size() > most_closed) return false;
        for (const std::size_t i : to_close) level.cells[i] = placed.cells[i] = LazorCell::blocked;
    }
}

} // namespace

std::optional<std::pair<std::uint64_t, std::uint64_t>>
lazor_difficulty_band(std::string_view name) {
    if (name == "easy") return std::pair<std::uint64_t, std::uint64_t>{0, 99};
    if (name == "medium") return std::pair<std::uint64_t, std::uint64_t>{100, 999};
    if (name == "hard")
        return std::pair<std::uint64_t, std::uint64_t>{1000,
                                                       std::numeric_limits<std::uint64_t>::max()};
    return std::nullopt;
}

std::string lazor_difficulty_name(std::uint64_t nodes) {
    return nodes < 100 ? "easy" : nodes < 1000 ? "medium" : "hard";
}

std::optional<LazorGenerated> generate_lazor_level(const LazorGenerateOptions& options) {
    std::mt19937_64 rng(options.seed);
    const int total = options.blocks[0] + options.blocks[1] + options.blocks[2];
    for (int attempt = 1; attempt <= options.attempts; ++attempt) {
        LazorLevel level;
        level.width = options.width;
        level.height = options.height;
        // About one cell in eight takes no block.
        int open = 0;
        for (int i = 0; i < options.width * options.height; ++i) {
            const bool blocked = draw(rng, 0, 7) == 0;
            level.cells.push_back(blocked ? LazorCell::blocked : LazorCell::open);
            open += blocked ? 0 : 1;
        }
        if (open < total) continue;
        for (int i = 0; i < options.lasers; ++i)
            level.lasers.push_back(side_laser(rng, options.width, options.height));
        level.blocks = options.blocks;

        LazorLevel placed = level;
        placed.blocks = {};
        std::vector<LazorCell> kinds;
        for (std::size_t k = 0; k < 3; ++k)
            kinds.insert(kinds.end(), options.blocks[k], lazor_blocks[k]);
        shuffle(kinds, rng);
        // Opaque blocks last: one stops a branch, so the blocks after it
        // would have fewer cells to go on.
        std::stable_partition(kinds.begin(), kinds.end(),
                              [](LazorCell k) { return k == LazorCell::opaque; });
        if (!place_on_paths(placed, kinds, rng)) continue;
        PointChooser chooser(placed, options.points, rng);
        if (!chooser.witness_blocks()) continue;
        if (options.unique &&
            !cut_other_solutions(level, placed, chooser, options.max_nodes, options.runner))
            continue;
        if (!chooser.fill_to(options.points)) continue;
        level.points = placed.points = chooser.chosen();

        LazorSolveOptions check;
        check.all = true;
        check.max_nodes = options.max_nodes;
        check.runner = options.runner;
        const LazorSolution s = solve_lazor(level, check);
        if (s.status != LazorSolution::Status::solved) continue; // a limit: too hard to count
        if (options.unique && s.solutions != "1") continue;
        if (s.nodes < options.difficulty.first || s.nodes > options.difficulty.second) continue;
        // The solution reported is the one the solver prints (with a unique
        // solution, the placement drawn).
        return LazorGenerated{level, *s.placed, attempt, s.nodes};
    }
    return std::nullopt;
}

} // namespace orthoray

// Generating levels (docs/puzzles.md, "Generation"): a random grid, lasers
// entering from its sides, the blocks placed one by one where the lasers
// go, and points that need every block; the solver's --all count decides
// whether the level is kept. Every draw goes
// through orthoray::uniform, so a seed gives the same level everywhere.
#include "orthoray/generate.hpp"
#include "orthoray/puzzle.hpp"

#include "puzzle/beam_walk.hpp"

#include <algorithm>
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

// Which of `points` the lasers of `placed` pass (open cells empty).
std::vector<bool> passed(LazorLevel placed, const std::vector<LazorPoint>& points) {
    placed.points = points;
    std::vector<puzzle::Content> cells;
    for (const LazorCell c : placed.cells)
        cells.push_back(c == LazorCell::open ? puzzle::empty : puzzle::content_of(c));
    puzzle::BeamWalk walk(placed);
    walk.walk(cells);
    return walk.lit_points();
}

// Places the blocks one at a time on cells the lasers enter, as a random
// descent of the solver's search tree: at each step the first open cell the
// lasers enter gets the next block or is passed over. A block placed
// downstream never moves the lasers upstream, so every block ends on a
// laser's path. False when the lasers run out of open cells first.
bool place_on_paths(LazorLevel& placed, std::vector<LazorCell> kinds, std::mt19937_64& rng) {
    std::vector<puzzle::Content> cells;
    for (const LazorCell c : placed.cells) cells.push_back(puzzle::content_of(c));
    puzzle::BeamWalk walk(placed);
    while (!kinds.empty()) {
        const int cell = walk.walk(cells);
        if (cell < 0) break;
        if (draw(rng, 0, 1) == 0) {
            placed.cells[cell] = kinds.back();
            cells[cell] = puzzle::content_of(kinds.back());
            kinds.pop_back();
        } else {
            cells[cell] = puzzle::empty; // passed over
        }
    }
    return kinds.empty();
}

// Points for `placed`: first, greedily, points whose darkness would show
// that a reflect or refract block was left out (each chosen to witness as
// many blocks not yet witnessed as possible), then the points the lasers
// pass that depend on the most blocks; never a laser's start. Opaque blocks only take light away,
// so nothing can witness them. Empty when `count` points cannot do that.
std::vector<LazorPoint> choose_points(const LazorLevel& placed, int count, std::mt19937_64& rng) {
    const std::vector<LazorPoint> all = midpoints(placed);
    std::vector<bool> lit = passed(placed, all);
    for (std::size_t i = 0; i < all.size(); ++i)
        for (const LazorLaser& l : placed.lasers)
            if (all[i].x == l.x && all[i].y == l.y) lit[i] = false;
    // witnesses[i]: the blocks whose removal leaves point i dark.
    std::vector<std::vector<int>> witnesses(all.size());
    int blocks = 0;
    for (std::size_t b = 0; b < placed.cells.size(); ++b) {
        if (placed.cells[b] != LazorCell::reflect && placed.cells[b] != LazorCell::refract)
            continue;
        LazorLevel without = placed;
        without.cells[b] = LazorCell::open;
        const std::vector<bool> still = passed(without, all);
        for (std::size_t i = 0; i < all.size(); ++i)
            if (lit[i] && !still[i]) witnesses[i].push_back(blocks);
        ++blocks;
    }
    std::vector<bool> witnessed(static_cast<std::size_t>(blocks), false);
    std::vector<std::size_t> chosen;
    for (int left = blocks; left > 0;) {
        std::vector<std::size_t> best;
        int most = 0;
        for (std::size_t i = 0; i < all.size(); ++i) {
            int gain = 0;
            for (const int b : witnesses[i]) gain += witnessed[b] ? 0 : 1;
            if (gain > most) best.clear(), most = gain;
            if (gain == most && gain > 0) best.push_back(i);
        }
        if (most == 0 || static_cast<int>(chosen.size()) == count) return {};
        const std::size_t pick = best[static_cast<std::size_t>(
            uniform(rng, 0, static_cast<std::int64_t>(best.size()) - 1))];
        chosen.push_back(pick);
        for (const int b : witnesses[pick]) {
            left -= witnessed[b] ? 0 : 1;
            witnessed[b] = true;
        }
    }
    // Then the points that depend on the most blocks, ties in random order.
    std::vector<std::size_t> rest;
    for (std::size_t i = 0; i < all.size(); ++i)
        if (lit[i] && std::find(chosen.begin(), chosen.end(), i) == chosen.end()) rest.push_back(i);
    shuffle(rest, rng);
    std::stable_sort(rest.begin(), rest.end(), [&](std::size_t a, std::size_t b) {
        return witnesses[a].size() > witnesses[b].size();
    });
    for (std::size_t i = 0; static_cast<int>(chosen.size()) < count; ++i) {
        if (i == rest.size()) return {};
        chosen.push_back(rest[i]);
    }
    std::sort(chosen.begin(), chosen.end());
    std::vector<LazorPoint> out;
    for (const std::size_t i : chosen) out.push_back(all[i]);
    return out;
}

} // namespace

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
        if (!place_on_paths(placed, kinds, rng)) continue;
        const std::vector<LazorPoint> points = choose_points(placed, options.points, rng);
        if (points.empty()) continue;
        level.points = points;
        placed.points = points;

        LazorSolveOptions check;
        check.all = true;
        check.max_nodes = options.max_nodes;
        const LazorSolution s = solve_lazor(level, check);
        if (s.status != LazorSolution::Status::solved) continue; // a limit: too hard to count
        if (options.unique && s.solutions != "1") continue;
        // The solution reported is the one the solver prints (with a unique
        // solution, the placement drawn).
        return LazorGenerated{level, *s.placed, attempt, s.nodes};
    }
    return std::nullopt;
}

} // namespace orthoray

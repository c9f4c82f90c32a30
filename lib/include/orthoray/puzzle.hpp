// Lazor levels (.bff files): reading them, turning a level into a scene of
// one-sided elements, and searching for a placement of the level's blocks
// that lights every point. The format, the model and the search are in
// docs/puzzles.md.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/scene.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace orthoray {

// What a cell of a level's grid holds: open (a block may be placed), blocked
// (no block may be), or a block: reflect (A, mirrors), opaque (B,
// absorbers), refract (C, splitters).
enum class LazorCell : std::uint8_t { open, blocked, reflect, opaque, refract };

// The three kinds of blocks, in the order the counts and the search use.
constexpr std::array<LazorCell, 3> lazor_blocks{LazorCell::reflect, LazorCell::opaque,
                                                LazorCell::refract};

// 'o', 'x', 'A', 'B', 'C'.
char lazor_letter(LazorCell cell);

// Positions are in half-block units, as in the file: x grows to the right,
// y downward, and block (column c, row r) covers [2c, 2c + 2] x [2r, 2r + 2].
struct LazorLaser {
    int x = 0, y = 0;   // on the midpoint of a cell edge (x + y odd)
    int dx = 1, dy = 1; // each 1 or -1
    int line = 0;
};

struct LazorPoint {
    int x = 0, y = 0;
    int line = 0;
};

struct LazorLevel {
    int width = 0, height = 0;    // in blocks
    std::vector<LazorCell> cells; // row by row from the top, width * height
    std::array<int, 3> blocks{};  // reflect, opaque, refract blocks to place
    std::vector<LazorLaser> lasers;
    std::vector<LazorPoint> points;
    // Where each cell's letter stands in its file (line, column), for messages.
    std::vector<std::pair<int, int>> cell_positions;

    LazorCell at(int column, int row) const { return cells[row * width + column]; }
};

// The largest grid side accepted, in blocks: the search keeps a bit for
// every (edge point, direction) pair.
constexpr int lazor_max_side = 64;

// Parses .bff text; `file` is only used in messages. Bad input throws
// InputError (orthoray/parse.hpp): `FILE:LINE:COL: found ..., expected ...`.
LazorLevel read_lazor_level(std::string_view text, const std::string& file = "<input>");
// Reads a .bff file through the capped input reader.
LazorLevel load_lazor_level(const std::string& path);

// The level as .bff text (read_lazor_level gives it back). `title` becomes a
// comment on the first line when not empty.
std::string write_lazor_level(const LazorLevel& level, const std::string& title = "");
// Only the grid, GRID START to GRID STOP.
std::string write_lazor_grid(const LazorLevel& level);

// `solved` read as a placement for `level`: the same grid size, the same
// fixed cells, and on the open cells exactly the level's blocks. Returns the
// level with those blocks fixed and no blocks left to place; a mismatch
// throws InputError at the offending cell of `solved` (from `solved_file`).
LazorLevel apply_lazor_placement(const LazorLevel& level, const LazorLevel& solved,
                                 const std::string& solved_file);

// The scene of docs/puzzles.md: every block on the grid as four one-sided
// elements facing outward, each laser a ray started half a step behind its
// file position, each point a target. Blocks still to place are not in it.
Scene lazor_scene(const LazorLevel& level);

// The search in independent pieces, and what runs them
// (orthoray/puzzle_pieces.hpp): threads by default, MPI ranks from the
// command line.
struct LazorPieceResult;
class LazorSearchPieces;
using LazorPieceRunner =
    std::function<std::vector<std::optional<LazorPieceResult>>(const LazorSearchPieces&)>;

struct LazorSolveOptions {
    unsigned jobs = 1;                       // threads; 0 means one per core
    bool all = false;                        // count every solution
    std::optional<std::uint64_t> max_nodes;  // search nodes before giving up
    const std::atomic<bool>* stop = nullptr; // set from outside (deadline, signal)
    // When set, every search node visited adds 1 (relaxed), for a progress
    // line read from another thread.
    std::atomic<std::uint64_t>* progress = nullptr;
    // When set, runs the pieces instead of `jobs` threads (stop, progress
    // and jobs are then its business); the answer is the same.
    const LazorPieceRunner* runner = nullptr;
};

struct LazorSolution {
    enum class Status { solved, unsolvable, limit };
    Status status = Status::limit;
    // solved: the level with the blocks placed (the first solution in the
    // search order of docs/puzzles.md, the same for any number of threads).
    std::optional<LazorLevel> placed;
    // With `all`: the number of placements that light every point (exact,
    // as a decimal string: it can exceed 64 bits on big open grids).
    std::string solutions;
    // Search nodes a one-thread search visits to its answer; at the node
    // budget, the budget (what one thread visits before it stops); at a
    // stop request, every node visited.
    std::uint64_t nodes = 0;
    // limit: which limit ("nodes" or "stop").
    std::string limit;
    // solved: for each point in file order, what solve() said of it on the
    // placed level's scene: the least reflections before a branch reaches
    // it, and the least-numbered laser that does (docs/optics.md).
    std::vector<TargetAnswer> points;
};

// Searches for a placement of exactly the level's blocks on open cells that
// lights every point. Every candidate is decided with the acting rule of
// docs/optics.md, and a placement found is checked once more by solve() on
// its scene before it is returned.
LazorSolution solve_lazor(const LazorLevel& level, const LazorSolveOptions& options = {});

// What `orthoray puzzle generate` builds (docs/puzzles.md, "Generation").
struct LazorGenerateOptions {
    int width = 5, height = 5;          // in blocks, 1 to lazor_max_side
    std::array<int, 3> blocks{3, 0, 0}; // reflect, opaque, refract blocks to place
    int lasers = 1, points = 3;         // at least 1 each
    bool unique = true;                 // only levels with exactly one solution
    std::uint64_t seed = 1;             // the same level for the same options
    int attempts = 500;                 // placements tried before giving up
    // Search nodes for each search on a candidate: each search for another
    // solution, and the final count of its solutions.
    std::uint64_t max_nodes = 50'000;
    // Only levels whose count of solutions (the solver, --all) takes from
    // first to second search nodes, both included: the difficulty.
    std::pair<std::uint64_t, std::uint64_t> difficulty{0,
                                                       std::numeric_limits<std::uint64_t>::max()};
    // When set, runs the pieces of every search (one thread without it);
    // the level is the same.
    const LazorPieceRunner* runner = nullptr;
};

struct LazorGenerated {
    LazorLevel level;        // the blocks to place, lasers and points
    LazorLevel solution;     // the same with the blocks placed
    int attempts = 0;        // candidates built, this one included
    std::uint64_t nodes = 0; // search nodes to count its solutions: its difficulty
};

// The difficulty bands of docs/puzzles.md ("Generation"), in search nodes to
// count a level's solutions: easy (up to 99), medium (100 to 999), hard
// (1000 and more). Nothing for another name.
std::optional<std::pair<std::uint64_t, std::uint64_t>> lazor_difficulty_band(std::string_view name);
// The band `nodes` falls in.
std::string lazor_difficulty_name(std::uint64_t nodes);

// A level whose points the intended placement lights (and, with `unique`,
// no other placement does, as the solver's count proves). Nothing when no
// candidate within `attempts` qualifies.
std::optional<LazorGenerated> generate_lazor_level(const LazorGenerateOptions& options);

} // namespace orthoray

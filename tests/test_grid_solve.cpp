// Grid mazes solved (docs/grid-mazes.md): the scene of a maze answers as
// the puzzle's own cell-by-cell walk does on thousands of random mazes, and
// the public samples of ../shared/puzzles/grid whose questions orthoray
// answers get their published answers.
#include "orthoray/grid.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "support/case_count.hpp"
#include "support/grid_walk.hpp"
#include "support/portable_random.hpp"
#include "support/run_cli.hpp"
#include "support/skip_test.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

using namespace orthoray;
using namespace orthoray::test;

namespace {

namespace fs = std::filesystem;

// Single trajectories go to the reference tracer, the engine that takes
// diagonal scenes today; the illumination question to the branch search.
Answer solve_maze(const GridMaze& maze, PathSink* path = nullptr) {
    SolveOptions options;
    const Scene scene = grid_scene(maze);
    if (scene.single_trajectory()) options.engine = Engine::reference;
    options.path = path;
    return solve(scene, options);
}

GridMaze instance_maze(const std::string& name) {
    const std::string path = instance("grid/" + name + ".grid");
    return read_grid_maze(read_file(path), path);
}

// The folder of the public grid samples; when it is not there, the test
// that asked is reported skipped (support/skip_test.hpp) and must return.
std::optional<fs::path> samples_folder_or_skip() {
    const fs::path folder = fs::path(source_path("..")) / "shared" / "puzzles" / "grid";
    if (fs::is_regular_file(folder / "expected.jsonl")) return folder;
    skip_test("no ../shared/puzzles/grid beside the source tree");
    return std::nullopt;
}

// The published answer of the case `name` in expected.jsonl.
long published(const fs::path& folder, const std::string& name) {
    std::ifstream in(folder / "expected.jsonl");
    for (std::string line; std::getline(in, line);) {
        const nlohmann::json record = nlohmann::json::parse(line);
        if (record.at("name") == name) return record.at("answer").get<long>();
    }
    FAIL("no case " << name << " in expected.jsonl");
    return 0;
}

GridMaze random_maze(std::mt19937_64& rng) {
    GridMaze maze;
    maze.width = pick(rng, 1, 7);
    maze.height = pick(rng, 1, 7);
    const int block_percent = pick(rng, 0, 20), mirror_percent = pick(rng, 10, 70);
    for (int i = 0; i < maze.width * maze.height; ++i)
        maze.cells.push_back(chance(rng, block_percent)     ? GridCell::block
                             : !chance(rng, mirror_percent) ? GridCell::empty
                             : chance(rng, 50)              ? GridCell::rising
                                                            : GridCell::falling);
    GridBeam beam;
    beam.side = static_cast<GridSide>(pick(rng, 0, 3));
    const bool row = beam.side == GridSide::left || beam.side == GridSide::right;
    beam.index = pick(rng, 0, (row ? maze.height : maze.width) - 1);
    maze.beams.push_back(beam);
    return maze;
}

GridTarget exit_target(GridSide side, int index) {
    GridTarget target;
    target.kind = GridTarget::Kind::exit;
    target.side = side;
    target.index = index;
    return target;
}

// The least number of cells to change so that the maze's scene answers yes
// (its exit target is reached), trying every set of that many cells of
// `candidates` and every choice of `choices` for each; nothing when no set
// of at most `most` cells does. The puzzles' search, done here by brute
// force around orthoray's answer for each grid.
std::optional<int> fewest_changes(GridMaze maze, const std::vector<int>& candidates,
                                  const std::function<std::vector<GridCell>(GridCell)>& choices,
                                  int most) {
    const std::vector<GridCell> original = maze.cells;
    std::function<bool(std::size_t, int)> some_set = [&](std::size_t from, int left) {
        if (left == 0) return solve_maze(maze).reason == Reason::hit;
        for (std::size_t i = from; i < candidates.size(); ++i) {
            const auto cell = static_cast<std::size_t>(candidates[i]);
            for (GridCell choice : choices(original[cell])) {
                maze.cells[cell] = choice;
                if (some_set(i + 1, left - 1)) return true;
            }
            maze.cells[cell] = original[cell];
        }
        return false;
    };
    for (int k = 0; k <= most; ++k)
        if (some_set(0, k)) return k;
    return std::nullopt;
}

} // namespace

TEST_CASE("a maze's scene answers as the puzzle's walk on random mazes", "[grid][property][slow]") {
    std::mt19937_64 rng(20261124);
    int exits = 0, absorbed = 0, lit = 0;
    for (int n = 0; n < case_count(2000); ++n) {
        GridMaze maze = random_maze(rng);
        const GridWalk walk = walk_grid(maze, maze.beams[0]);
        CAPTURE(n, write_scene(grid_scene(maze)));
        // No target: how the beam ends, after how many mirrors.
        const Answer end = solve_maze(maze);
        CHECK(end.reason == (walk.absorbed ? Reason::absorbed : Reason::escape));
        CHECK(end.reflections == walk.mirror_hits);
        (walk.absorbed ? absorbed : exits) += 1;
        // The way out the walk found is reached, after every mirror hit.
        if (!walk.absorbed) {
            maze.targets = {exit_target(walk.exit_side, walk.exit_index)};
            const Answer out = solve_maze(maze);
            CHECK(out.reason == Reason::hit);
            CHECK(out.reflections == walk.mirror_hits);
        }
        // Every cell centre as a target: lit exactly where the walk passed,
        // after as many mirrors as the walk hit before it got there.
        maze.targets.clear();
        for (int r = 0; r < maze.height; ++r)
            for (int c = 0; c < maze.width; ++c) {
                GridTarget target;
                target.row = r;
                target.column = c;
                maze.targets.push_back(target);
            }
        // One more, so that a one-cell maze asks the illumination question too.
        maze.targets.push_back(exit_target(maze.beams[0].side, maze.beams[0].index));
        const Answer cells = solve_maze(maze);
        REQUIRE(cells.targets.size() == maze.cells.size() + 1);
        for (std::size_t i = 0; i < maze.cells.size(); ++i) {
            CAPTURE(i);
            const TargetAnswer& t = cells.targets[i];
            CHECK((t.status == TargetAnswer::Status::lit) == (walk.first_reached[i] >= 0));
            if (walk.first_reached[i] >= 0) {
                CHECK(t.reflections == walk.first_reached[i]);
                ++lit;
            }
        }
    }
    CHECK(exits > case_count(2000) / 2);
    CHECK(absorbed > case_count(2000) / 10);
    CHECK(lit > case_count(2000) * 2);
}

TEST_CASE("samples: mirror hits before the beam leaves (Samsung mirror game)", "[grid][samples]") {
    const auto folder = samples_folder_or_skip();
    if (!folder) return;
    for (const std::string name : {"samsung-mirror-game-1", "samsung-mirror-game-2",
                                   "samsung-mirror-game-3", "samsung-mirror-game-4"}) {
        CAPTURE(name);
        const Answer a = solve_maze(instance_maze(name));
        CHECK(a.reason == Reason::escape);
        CHECK(a.reflections == published(*folder, name));
    }
}

TEST_CASE("samples: the most reflections over every entry (USACO Mirror Field)",
          "[grid][samples]") {
    const auto folder = samples_folder_or_skip();
    if (!folder) return;
    const std::string name = "usaco2014feb-bronze-mirror-field";
    GridMaze maze = instance_maze(name);
    long most = -1;
    int entries = 0;
    for (GridSide side : {GridSide::left, GridSide::right, GridSide::top, GridSide::bottom}) {
        const bool row = side == GridSide::left || side == GridSide::right;
        for (int i = 0; i < (row ? maze.height : maze.width); ++i) {
            maze.beams = {GridBeam{side, i, 0}};
            const Answer a = solve_maze(maze);
            // Two-sided mirrors and a beam from outside: it always leaves,
            // so the puzzle's -1 (reflecting forever) cannot happen.
            CHECK(a.reason == Reason::escape);
            most = std::max(most, a.reflections.get_si());
            ++entries;
        }
    }
    CHECK(entries == 12);
    CHECK(most == published(*folder, name));
}

TEST_CASE("samples: cells entered before the beam leaves, from the path (paiza)",
          "[grid][samples]") {
    const auto folder = samples_folder_or_skip();
    if (!folder) return;
    const std::string name = "paiza-beam-reflection-1";
    const GridMaze maze = instance_maze(name);
    PathRecorder path;
    const Answer a = solve_maze(maze, &path);
    REQUIRE(a.reason == Reason::escape);
    // Each cell crossed adds 1 to the path's length: the beam starts half a
    // cell outside and goes on from its last turn to the side of the grid.
    REQUIRE(!path.points.empty());
    Rational length = 0;
    for (std::size_t i = 1; i < path.points.size(); ++i)
        length += abs(path.points[i][0] - path.points[i - 1][0]) +
                  abs(path.points[i][1] - path.points[i - 1][1]);
    const Vector& last = path.points.back();
    const Vector& d = path.directions.back();
    length += d[0] > 0   ? Rational(maze.width - last[0])
              : d[0] < 0 ? last[0]
              : d[1] > 0 ? Rational(maze.height - last[1])
                         : last[1];
    length -= Rational(1, 2);
    CHECK(length == published(*folder, name));
    CHECK(length == walk_grid(maze, maze.beams[0]).cell_entries);
}

TEST_CASE("samples: fewest mirror flips, each flipped grid decided by orthoray (DMOPC)",
          "[grid][samples][slow]") {
    const auto folder = samples_folder_or_skip();
    if (!folder) return;
    const auto flip = [](GridCell cell) {
        return std::vector<GridCell>{cell == GridCell::rising ? GridCell::falling
                                                              : GridCell::rising};
    };
    for (const std::string name : {"dmopc21c10p3-mirror-flips-1", "dmopc21c10p3-mirror-flips-2"}) {
        CAPTURE(name);
        const GridMaze maze = instance_maze(name);
        std::vector<int> every(maze.cells.size());
        for (std::size_t i = 0; i < every.size(); ++i) every[i] = static_cast<int>(i);
        const long answer = published(*folder, name);
        // Searching up to every cell proves -1; else one past the answer is never needed.
        const int most = answer < 0 ? static_cast<int>(every.size()) : static_cast<int>(answer);
        const std::optional<int> fewest = fewest_changes(maze, every, flip, most);
        CHECK(fewest.value_or(-1) == answer);
    }
}

TEST_CASE("samples: fewest mirrors added, each grid decided by orthoray (TopCoder)",
          "[grid][samples]") {
    const auto folder = samples_folder_or_skip();
    if (!folder) return;
    const auto add = [](GridCell) {
        return std::vector<GridCell>{GridCell::rising, GridCell::falling};
    };
    for (const std::string name :
         {"topcoder-srm237-mirrorplacement-1", "topcoder-srm237-mirrorplacement-2"}) {
        CAPTURE(name);
        const GridMaze maze = instance_maze(name);
        std::vector<int> open;
        for (std::size_t i = 0; i < maze.cells.size(); ++i)
            if (maze.cells[i] == GridCell::empty) open.push_back(static_cast<int>(i));
        const long answer = published(*folder, name);
        REQUIRE(answer >= 0);
        CHECK(fewest_changes(maze, open, add, static_cast<int>(answer)).value_or(-1) == answer);
    }
}

TEST_CASE("samples: puzzle splitters are refused where they stand (Advent of Code)",
          "[grid][samples]") {
    const auto folder = samples_folder_or_skip();
    if (!folder) return;
    // The published grid under a header of our own: the first '|' is
    // refused, at its row (line 3) and column.
    const std::string text = "beam left 0\ngrid\n" + slurp((*folder / "aoc2023-d16-part1.txt"));
    try {
        read_grid_maze(text, "aoc.grid");
        FAIL("a grid with splitters was read");
    } catch (const InputError& e) {
        CHECK(e.line() == 3);
        CHECK(e.column() == 2);
        CHECK(e.message().find("a puzzle splitter that sends a beam both ways") !=
              std::string::npos);
    }
}

TEST_CASE("samples that are scenes: the first corner receptor of a square room (LeetCode 858)",
          "[grid][samples]") {
    const auto folder = samples_folder_or_skip();
    if (!folder) return;
    for (const std::string name :
         {"leetcode858-mirror-reflection-1", "leetcode858-mirror-reflection-2"}) {
        CAPTURE(name);
        int p = 0, q = 0;
        REQUIRE(std::sscanf(slurp((*folder / (name + ".txt")).string()).c_str(), "p = %d, q = %d",
                            &p, &q) == 2);
        // A p x p mirror box; receptors 0, 1, 2 at the SE, NE and NW corners
        // are targets 1, 2, 3; the ray leaves the SW corner toward (p, q).
        Scene room;
        room.add_mirror(0, 0, {{0, p}});
        room.add_mirror(0, p, {{0, p}});
        room.add_mirror(1, 0, {{0, p}});
        room.add_mirror(1, p, {{0, p}});
        room.ray().direction = {Rational(p), Rational(q), Rational(0)};
        room.targets = {{Rational(p), Rational(0), Rational(0)},
                        {Rational(p), Rational(p), Rational(0)},
                        {Rational(0), Rational(p), Rational(0)}};
        const Answer a = solve(room);
        REQUIRE(a.targets.size() == 3);
        // The receptor reached first absorbs the ray: the lit target with
        // the fewest reflections before it.
        long first = -1;
        for (std::size_t i = 0; i < 3; ++i)
            if (a.targets[i].status == TargetAnswer::Status::lit &&
                (first < 0 || a.targets[i].reflections < a.targets[first].reflections))
                first = static_cast<long>(i);
        CHECK(first == published(*folder, name));
    }
}

TEST_CASE("samples that are scenes: the first mirror whose toggle lets the gaze through (USACO "
          "Mirrors)",
          "[grid][samples]") {
    const auto folder = samples_folder_or_skip();
    if (!folder) return;
    const std::string name = "usaco2013jan-bronze-mirrors";
    std::istringstream in(slurp((*folder / (name + ".txt")).string()));
    int n = 0, a = 0, b = 0;
    REQUIRE(in >> n >> a >> b);
    struct PointMirror {
        int x, y;
        char slope;
    };
    std::vector<PointMirror> mirrors(static_cast<std::size_t>(n));
    for (PointMirror& m : mirrors) REQUIRE(in >> m.x >> m.y >> m.slope);
    // Short mirrors centred on integer points: the gaze starts on integer
    // lines and turns only at integer points, so it meets a mirror only at
    // its centre, and a mirror's length (1 here) does not matter.
    const auto answer_with = [&](std::size_t toggled) {
        Scene scene;
        const Rational h(1, 2);
        for (std::size_t i = 0; i < mirrors.size(); ++i) {
            const PointMirror& m = mirrors[i];
            const bool rising = (m.slope == '/') != (i + 1 == toggled);
            const Rational low = m.y - h, high = m.y + h;
            scene.add_diagonal(ElementKind::mirror, m.x - h, rising ? low : high, m.x + h,
                               rising ? high : low);
        }
        scene.ray().direction = {Rational(1), Rational(0), Rational(0)};
        scene.target() = {Rational(a), Rational(b), Rational(0)};
        SolveOptions options;
        options.engine = Engine::reference;
        return solve(scene, options).reason == Reason::hit;
    };
    long first = -1;
    for (std::size_t toggled = 0; toggled <= mirrors.size() && first < 0; ++toggled)
        if (answer_with(toggled)) first = static_cast<long>(toggled);
    CHECK(first == published(*folder, name));
}

TEST_CASE("solve answers a .grid file from the command line", "[grid][cli]") {
    const CliResult r =
        run_cli("solve --engine reference " + quote(instance("grid/samsung-mirror-game-2.grid")));
    CHECK(r.status == 1);
    CHECK(r.out.find("reason       escape\nreflections  3\n") != std::string::npos);
}

TEST_CASE("the certificates of a maze's answers verify against the .grid file", "[grid][cli]") {
    TempDir dir;
    const std::string maze = instance("grid/samsung-mirror-game-1.grid");
    const std::string cert = dir.path("s1.cert");
    CHECK(run_cli("solve --engine reference " + quote(maze) + " --certificate " + quote(cert))
              .status == 1);
    const CliResult valid = run_cli("verify " + quote(maze) + ' ' + quote(cert));
    CHECK(valid.status == 0);
    CHECK(valid.out == "valid: escape, 7 reflections\n");
    // The same path does not fit another maze.
    const CliResult other =
        run_cli("verify " + quote(instance("grid/samsung-mirror-game-2.grid")) + ' ' + quote(cert));
    CHECK(other.status == 1);
    CHECK(other.out.rfind("invalid: ", 0) == 0);

    const std::string example = instance("grid/example.grid");
    const std::string lit = dir.path("example.cert");
    CHECK(run_cli("solve " + quote(example) + " --certificate " + quote(lit)).status == 1);
    const CliResult checked = run_cli("verify " + quote(example) + ' ' + quote(lit));
    CHECK(checked.status == 0);
    CHECK(checked.out == "valid: unlit, 3 reflections, 1 states\n");
}

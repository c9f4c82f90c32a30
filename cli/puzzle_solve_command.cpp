// orthoray puzzle solve LEVEL.bff: find a placement of the level's blocks that
// lights every point (docs/puzzles.md, "The search").
#include "commands.hpp"
#include "mpi_link.hpp"
#include "option_checks.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/puzzle.hpp"
#include "orthoray/puzzle_pieces.hpp"
#include "orthoray/render.hpp"
#include "orthoray/solve.hpp"
#include "output_file.hpp"
#include "phase_progress.hpp"
#include "puzzle_json.hpp"
#include "puzzle_mpi.hpp"
#include "run_monitor.hpp"
#include "stop_watcher.hpp"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

namespace orthoray::cli {
namespace {

struct PuzzleSolveArgs {
    std::string level, out, picture;
    bool json = false, all = false, quiet = false, mpi = false;
    unsigned jobs = 0;
    double timeout = 0;
    std::uint64_t max_nodes = 0;
};

using Clock = std::chrono::steady_clock;

void print_json(const LazorSolution& s, const std::string& limit, unsigned jobs, double seconds) {
    std::cout << '{' << lazor_json_members(s, limit, jobs, seconds) << "}\n";
}

void print_text(const LazorSolution& s, const std::string& limit, double seconds) {
    if (s.placed) std::cout << write_lazor_grid(*s.placed);
    for (std::size_t i = 0; i < s.points.size(); ++i)
        std::printf("point %zu (%d, %d)  lit by laser %zu after %s reflections\n", i + 1,
                    s.placed->points[i].x, s.placed->points[i].y, s.points[i].ray,
                    s.points[i].reflections.get_str().c_str());
    std::printf("answer       %s\n", lazor_answer_word(s.status));
    if (s.status == LazorSolution::Status::limit)
        std::printf("reason       limit (%s)\n", limit == "time"    ? "--timeout reached"
                                                 : limit == "nodes" ? "--max-nodes reached"
                                                                    : "interrupted");
    if (!s.solutions.empty()) std::printf("solutions    %s\n", s.solutions.c_str());
    std::printf("nodes        %llu\n", static_cast<unsigned long long>(s.nodes));
    std::printf("time         %.3f ms\n", seconds * 1e3);
}

// The lines between the level's cells, in the scene's units (a block is 2
// units wide, docs/puzzles.md), for the interactive viewer.
std::vector<std::pair<Vector, Vector>> cell_grid(const LazorLevel& level) {
    std::vector<std::pair<Vector, Vector>> lines;
    const Rational width(2 * level.width), height(2 * level.height);
    for (int c = 0; c <= level.width; ++c)
        lines.push_back({{Rational(2 * c), 0, 0}, {Rational(2 * c), height, 0}});
    for (int r = 0; r <= level.height; ++r)
        lines.push_back({{0, Rational(2 * r), 0}, {width, Rational(2 * r), 0}});
    return lines;
}

// The solved level's scene as SVG, or as the interactive viewer when the
// name ends in .html (with the cell grid): every branch of every laser (at
// most 10^5 states), each point marked lit or not by the illumination
// engine, as `orthoray render` draws scenes with splitters and several rays.
void write_picture(const LazorLevel& solved, const PuzzleSolveArgs& args, OutputFile& out) {
    const Scene scene = lazor_scene(solved);
    const bool html = args.picture.ends_with(".html") || args.picture.ends_with(".HTML");
    RenderOptions options;
    if (html) options.viewer_segments = 5000;
    SceneRenderer renderer(scene, options);
    renderer.add_caption("solved " + args.level + ": " + std::to_string(solved.points.size()) +
                         " points, " + std::to_string(scene.rays.size()) + " lasers");
    walk_branches(scene, renderer, 100'000);
    const Answer answer = solve(scene);
    // A level of one laser and one point is a single trajectory: its one
    // target is lit when the answer is yes.
    std::vector<TargetAnswer> targets = answer.targets;
    if (!answer.illumination()) {
        targets.assign(1, TargetAnswer{});
        targets[0].status = answer.yes() ? TargetAnswer::Status::lit : TargetAnswer::Status::unlit;
    }
    renderer.mark_targets(targets);
    if (!html) {
        renderer.write_svg(out.stream());
    } else {
        renderer.add_caption(std::string("answer ") + answer_word(answer) +
                             (answer.yes() ? ": the placement shown lights every point" : ""));
        renderer.set_grid(cell_grid(solved));
        renderer.write_html(out.stream(), "orthoray puzzle: " + args.level);
    }
    out.commit();
}

std::optional<Clock::time_point> deadline_of(const PuzzleSolveArgs& args) {
    if (args.timeout <= 0) return std::nullopt;
    return Clock::now() + std::chrono::duration_cast<std::chrono::nanoseconds>(
                              std::chrono::duration<double>(args.timeout));
}

// The search and its report. `stop` and `nodes` are the flag the deadline
// and signals set and the progress line's count; with MPI, `runner` runs
// the pieces on the ranks, and `ranks` is their number (0 without).
int search_level(const PuzzleSolveArgs& args, const CLI::Option* max_nodes, std::atomic<bool>& stop,
                 std::atomic<std::uint64_t>& nodes, const LazorPieceRunner* runner,
                 unsigned ranks) {
    const std::optional<Clock::time_point> deadline = deadline_of(args);
    const InterruptGuard interrupts;
    const LazorLevel level = load_lazor_level(args.level); // bad input ends here
    // Refuse a bad output path before searching.
    refuse_same_output(args.out, "the solved level", args.picture, "the picture");
    std::optional<OutputFile> out;
    if (!args.out.empty())
        out.emplace(args.out, std::vector<std::string>{args.level}, "the solved level");
    std::optional<OutputFile> picture;
    if (!args.picture.empty())
        picture.emplace(args.picture, std::vector<std::string>{args.level, args.out},
                        "the picture");

    LazorSolveOptions options;
    options.jobs = args.jobs;
    options.runner = runner;
    options.all = args.all;
    options.stop = &stop;
    if (max_nodes->count() > 0) options.max_nodes = args.max_nodes;
    LazorSolution solution;
    bool interrupted = false;
    const Clock::time_point begin_search = Clock::now();
    {
        // The line shows the nodes the search has visited (docs/limits.md).
        options.progress = &nodes;
        PhaseProgress progress("puzzle solve", !args.quiet);
        progress.phase("searching " + args.level, &nodes, "nodes");
        const StopWatcher watcher(stop, deadline);
        solution = solve_lazor(level, options);
        interrupted = watcher.interrupted();
        progress.finish();
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - begin_search).count();
    // A stop that is not the node budget is the deadline only once it has
    // passed: under MPI a worker's signal stops its pieces, which rank 0's
    // watcher never sees.
    const bool timed_out = !interrupted && deadline && Clock::now() >= *deadline;
    const std::string limit = solution.limit == "nodes" ? "nodes"
                              : timed_out               ? "time"
                                                        : "interrupt";
    const unsigned jobs = ranks > 0       ? ranks
                          : args.jobs > 0 ? args.jobs
                                          : std::max(1u, std::thread::hardware_concurrency());
    if (out && solution.placed) {
        out->stream() << write_lazor_level(*solution.placed,
                                           "solved by orthoray puzzle solve: " + args.level);
        out->commit();
    }
    if (picture && solution.placed) write_picture(*solution.placed, args, *picture);
    if (args.json)
        print_json(solution, limit, jobs, seconds);
    else
        print_text(solution, limit, seconds);
    switch (solution.status) {
    case LazorSolution::Status::solved:
        return yes;
    case LazorSolution::Status::unsolvable:
        return no;
    case LazorSolution::Status::limit:
        break;
    }
    return Exit::limit;
}

int run(const PuzzleSolveArgs& args, const CLI::Option* max_nodes) {
    std::atomic<bool> stop{false};
    std::atomic<std::uint64_t> nodes{0};
    if (!args.mpi) return search_level(args, max_nodes, stop, nodes, nullptr, 0);
#ifdef ORTHORAY_MPI
    const MpiSession session;
    if (session.rank != 0) { // a worker: its own deadline and signals stop its pieces
        const InterruptGuard interrupts;
        const StopWatcher watcher(stop, deadline_of(args));
        serve_pieces(stop);
        return yes;
    }
    PieceCoordinator coordinator(session.size, &stop, &nodes);
    return coordinator.run_command([&](const LazorPieceRunner& runner) {
        return search_level(args, max_nodes, stop, nodes, &runner,
                            static_cast<unsigned>(session.size));
    });
#else
    throw UsageError("found --mpi, expected a build with MPI (cmake -DORTHORAY_MPI=ON; "
                     "docs/puzzles.md)");
#endif
}

} // namespace

Command add_puzzle_solve(CLI::App& puzzle) {
    auto args = std::make_shared<PuzzleSolveArgs>();
    CLI::App* cmd = puzzle.add_subcommand(
        "solve", "Find a placement of exactly the level's blocks on its open cells that lights\n"
                 "every point, and print the solved grid (.bff GRID syntax). The placement\n"
                 "printed is the first in the search order of docs/puzzles.md, the same for\n"
                 "any --jobs; it is checked once more by the illumination engine on the\n"
                 "level's scene.\n\n"
                 "Example:\n"
                 "  orthoray puzzle solve level.bff -o solved.bff\n\n"
                 "Exit status: 0 solved, 1 proven unsolvable (the whole space searched),\n"
                 "2 bad input or usage, 3 a limit (--timeout, --max-nodes, SIGINT or SIGTERM)\n"
                 "stopped the search first, 5 an output could not be written.");
    cmd->add_option("LEVEL", args->level, "the level (.bff)")->required();
    cmd->add_flag(
        "--json", args->json,
        "print one JSON object: answer (solved, unsolvable, unknown), grid (rows), points, "
        "solutions (with --all), nodes, jobs, seconds");
    cmd->add_option("-o,--output", args->out,
                    "write the solved level here (.bff, the blocks placed in its grid)")
        ->check(not_empty("a file name"));
    cmd->add_option("--render", args->picture,
                    "draw the solved level here (SVG, or the interactive viewer with the "
                    "cell grid when the name ends in .html): every laser's branches, each "
                    "point gold when lit (as 'orthoray render' draws scenes)")
        ->check(not_empty("a file name"));
    cmd->add_option("--jobs", args->jobs, "threads (default: one per core)")
        ->transform(whole_number_in(1, 1024));
    cmd->add_flag("--mpi", args->mpi,
                  "spread the search over the ranks of 'mpirun -n P orthoray puzzle solve ... "
                  "--mpi': the same answer, printed by rank 0 (docs/puzzles.md)");
    cmd->add_flag("--all", args->all,
                  "search the whole space and count every placement that lights every point");
    cmd->add_option("--timeout", args->timeout,
                    "stop after SECONDS (a decimal, counted from the start): answer unknown, "
                    "exit 3")
        ->check(timeout_seconds());
    CLI::Option* max_nodes =
        cmd->add_option("--max-nodes", args->max_nodes,
                        "visit at most N search nodes; without an answer by then, exit 3")
            ->transform(whole_number_u64());
    cmd->add_flag("--quiet", args->quiet,
                  "no progress line (it is drawn on a terminal after a second: nodes, rate, "
                  "time)");
    return [args, max_nodes] { return run(*args, max_nodes); };
}

} // namespace orthoray::cli

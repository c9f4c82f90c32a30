// solve_lazor(): the placement search over threads (docs/puzzles.md, "The
// search"). The top of the search tree is split into subtrees in search
// order, the same split whatever the number of threads; threads take them in
// order. The answer is the first solution of the first subtree that has one,
// so it does not depend on which thread finished first.
#include "orthoray/puzzle.hpp"
#include "orthoray/solve.hpp"

#include "puzzle/placement_search.hpp"

#include <mutex>
#include <stdexcept>
#include <thread>

namespace orthoray {
namespace {

using puzzle::Board;
using puzzle::Decision;
using puzzle::PlacementSearch;
using puzzle::SubtreeResult;

// Enough subtrees to keep every core busy while one runs long; the split
// does not depend on the number of threads.
constexpr std::size_t split_target = 64;

std::vector<std::vector<Decision>> split(PlacementSearch& search) {
    std::vector<std::vector<Decision>> tasks{{}};
    while (tasks.size() < split_target) {
        std::vector<std::vector<Decision>> next;
        bool expanded = false;
        for (const std::vector<Decision>& path : tasks) {
            const std::vector<Decision> children = search.children(path);
            if (children.empty()) {
                next.push_back(path); // a leaf or pruned: searched as it is
                continue;
            }
            expanded = true;
            for (const Decision& d : children) {
                next.push_back(path);
                next.back().push_back(d);
            }
        }
        tasks = std::move(next);
        if (!expanded) break;
    }
    return tasks;
}

// The level with the blocks of a solution leaf: the decided cells as they
// are, and the blocks left on the undecided cells in row-major order,
// reflect blocks first, then opaque, then refract (any arrangement lights
// the same points, since no branch enters those cells).
LazorLevel placement_of(const LazorLevel& level, Board board) {
    LazorLevel placed = level;
    for (std::size_t i = 0; i < board.cells.size(); ++i) {
        puzzle::Content c = board.cells[i];
        if (c == puzzle::undecided) {
            c = puzzle::empty;
            for (int k = 0; k < 3; ++k)
                if (board.remaining[k] > 0) {
                    --board.remaining[k];
                    c = static_cast<puzzle::Content>(k + 1);
                    break;
                }
        }
        if (level.cells[i] == LazorCell::open)
            placed.cells[i] = c == puzzle::empty ? LazorCell::open : lazor_blocks[c - 1];
    }
    placed.blocks = {};
    return placed;
}

// The solution once more, by the library's own illumination engine on the
// translated scene: a disagreement is a bug, not an answer. Returns what
// the engine says of each point.
std::vector<TargetAnswer> recheck(const LazorLevel& placed) {
    const Answer answer = solve(lazor_scene(placed));
    if (!answer.yes())
        throw std::logic_error("the placement search found a placement that solve() says "
                               "leaves a point unlit");
    if (answer.illumination()) return answer.targets;
    // One laser, one point, no splitter: a single trajectory that hits.
    TargetAnswer hit;
    hit.status = TargetAnswer::Status::lit;
    hit.reflections = answer.reflections;
    hit.ray = 1;
    return {hit};
}

} // namespace

LazorSolution solve_lazor(const LazorLevel& level, const LazorSolveOptions& options) {
    const unsigned jobs =
        options.jobs > 0 ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
    std::atomic<std::uint64_t> nodes{0};
    std::atomic<bool> node_limit{false};
    // Asked once a search node.
    auto stop = [&] {
        if (options.progress) options.progress->fetch_add(1, std::memory_order_relaxed);
        if (options.stop && options.stop->load(std::memory_order_relaxed)) return true;
        if (!options.max_nodes) return false;
        if (nodes.fetch_add(1, std::memory_order_relaxed) < *options.max_nodes) return false;
        node_limit = true;
        return true;
    };

    PlacementSearch splitter(level, options.all, [] { return false; });
    const std::vector<std::vector<Decision>> tasks = split(splitter);
    std::vector<SubtreeResult> results(tasks.size());
    // Without --all, the least subtree index holding a solution so far:
    // later subtrees cannot change the answer and stop.
    std::atomic<std::size_t> best{tasks.size()};
    std::atomic<std::size_t> next_task{0};
    auto worker = [&] {
        std::size_t current = 0;
        PlacementSearch search(level, options.all, [&] {
            return stop() || (!options.all && best.load(std::memory_order_relaxed) < current);
        });
        while (true) {
            current = next_task.fetch_add(1);
            if (current >= tasks.size()) return;
            if (!options.all && best.load() < current) continue;
            results[current] = search.search(tasks[current]);
            if (!options.all && results[current].first) {
                std::size_t seen = best.load();
                while (current < seen && !best.compare_exchange_weak(seen, current)) {
                }
            }
        }
    };
    std::vector<std::thread> threads;
    for (unsigned t = 1; t < std::min<std::size_t>(jobs, tasks.size()); ++t)
        threads.emplace_back(worker);
    worker();
    for (std::thread& t : threads) t.join();

    LazorSolution solution;
    Integer count = 0;
    bool complete = true;
    for (const SubtreeResult& r : results) solution.nodes += r.nodes;
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        const SubtreeResult& r = results[i];
        if (!options.all && solution.placed) break;
        if (!r.complete) {
            complete = false;
            if (!options.all) break; // an earlier subtree may hold the first solution
            continue;
        }
        if (r.first && !solution.placed) solution.placed = placement_of(level, *r.first);
        count += r.solutions;
    }
    if (!complete) {
        solution.status = LazorSolution::Status::limit;
        solution.limit = node_limit ? "nodes" : "stop";
        solution.placed.reset();
        return solution;
    }
    if (options.all) solution.solutions = count.get_str();
    if (!solution.placed) {
        solution.status = LazorSolution::Status::unsolvable;
        return solution;
    }
    solution.points = recheck(*solution.placed);
    solution.status = LazorSolution::Status::solved;
    return solution;
}

} // namespace orthoray

#include "batch_level.hpp"

#include "commands.hpp"
#include "puzzle_json.hpp"
#include "stop_watcher.hpp"

#include <atomic>
#include <new>

namespace orthoray::cli {

Outcome decide_level(const LazorLevel& level, const std::string& head, const BatchArgs& args,
                     std::chrono::steady_clock::time_point begin) {
    std::atomic<bool> stop{false};
    LazorSolveOptions options; // one thread: batch runs instances side by side
    options.stop = &stop;
    // A placement search takes no reflection steps; its unit of work is the
    // search node, so --max-steps N caps the nodes as --max-nodes N would.
    if (args.choices.max_steps_option && args.choices.max_steps_option->count() > 0)
        options.max_nodes = args.choices.max_steps;
    LazorSolution solution;
    std::string limit_word;
    try {
        const StopWatcher watcher(stop, args.choices.deadline(begin));
        solution = solve_lazor(level, options);
        if (solution.status == LazorSolution::Status::limit)
            limit_word = solution.limit == "nodes" ? "nodes"
                         : watcher.interrupted()   ? "interrupt"
                                                   : "time";
    } catch (const std::bad_alloc&) {
        solution = LazorSolution{};
        limit_word = "memory";
    }
    // Not decided, so not recorded: --resume searches it again.
    if (limit_word == "interrupt") return {Ending::interrupted, {}};
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    Ending ending = Ending::limit;
    int status = Exit::limit;
    if (solution.status == LazorSolution::Status::solved) {
        ending = Ending::yes;
        status = yes;
    } else if (solution.status == LazorSolution::Status::unsolvable) {
        ending = Ending::no;
        status = no;
    }
    return {ending, head + ',' + lazor_json_members(solution, limit_word, 1, seconds) +
                        ",\"status\":" + std::to_string(status) + '}'};
}

} // namespace orthoray::cli

// orthoray puzzle scene LEVEL.bff: the level as a scene (docs/puzzles.md), so
// that `orthoray solve` decides which points a placement lights.
#include "commands.hpp"
#include "option_checks.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/puzzle.hpp"
#include "output_file.hpp"
#include "stop_at_once.hpp"

#include <iostream>
#include <memory>
#include <optional>
#include <vector>

namespace orthoray::cli {
namespace {

struct PuzzleSceneArgs {
    std::string level, placement, out;
    double timeout = 0;
};

int run(const PuzzleSceneArgs& args, const CLI::Option* timeout) {
    stop_at_once(timeout->count() > 0 ? std::optional<double>(args.timeout) : std::nullopt);
    // The output is opened first, so that a path it cannot be written to is
    // refused before any reading, as by every other command.
    std::optional<OutputFile> out;
    if (!args.out.empty()) {
        std::vector<std::string> inputs{args.level};
        if (!args.placement.empty()) inputs.push_back(args.placement);
        out.emplace(args.out, inputs, "the scene");
    }
    LazorLevel level = load_lazor_level(args.level);
    if (!args.placement.empty())
        level = apply_lazor_placement(level, load_lazor_level(args.placement), args.placement);
    const std::string text = write_scene(lazor_scene(level));
    // Decided: a stop from here on would cut the bytes short where they go
    // out in place (standard output, /dev/stdout), so the command finishes.
    stop_no_more();
    if (!out) {
        std::cout << text;
        return yes;
    }
    out->stream() << text;
    out->commit();
    return yes;
}

} // namespace

Command add_puzzle_scene(CLI::App& puzzle) {
    auto args = std::make_shared<PuzzleSceneArgs>();
    CLI::App* cmd = puzzle.add_subcommand(
        "scene", "Write a level as a .scene: each block four one-sided elements facing\n"
                 "outward, each laser a ray, each point a target (docs/puzzles.md). With\n"
                 "--placement, the blocks of a solved grid are in it, so 'orthoray solve'\n"
                 "says whether that placement lights every point.\n\n"
                 "Example:\n"
                 "  orthoray puzzle scene level.bff --placement solved.bff -o level.scene\n"
                 "  orthoray solve level.scene\n\n"
                 "Exit status: 0 written, 2 bad input or usage, 3 stopped by --timeout,\n"
                 "SIGINT or SIGTERM, 5 a failed write.");
    cmd->add_option("LEVEL", args->level, "the level (.bff)")->required();
    cmd->add_option("--placement", args->placement,
                    "a solved grid for this level (.bff, as 'puzzle solve -o' writes it): the "
                    "level's fixed cells, and exactly its blocks on open cells");
    cmd->add_option("-o,--output", args->out, "write the scene here instead of to stdout")
        ->check(not_empty("a file name"));
    CLI::Option* timeout = add_timeout_option(cmd, args->timeout, "the translation");
    return [args, timeout] { return run(*args, timeout); };
}

} // namespace orthoray::cli

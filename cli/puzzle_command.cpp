// orthoray puzzle: Lazor levels (.bff), docs/puzzles.md: scene, solve, generate. The subcommands
// live in their own files; this one only groups them.
#include "commands.hpp"

namespace orthoray::cli {

Command add_puzzle(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "puzzle", "Lazor levels (.bff files): translate one to a scene, find a placement of\n"
                  "its blocks that lights every point, or generate new levels with a unique\n"
                  "solution (docs/puzzles.md).\n\n"
                  "Example:\n"
                  "  orthoray puzzle solve level.bff -o solved.bff\n"
                  "  orthoray puzzle scene level.bff --placement solved.bff -o level.scene\n"
                  "  orthoray solve level.scene\n"
                  "  orthoray puzzle generate --size 5x5 --blocks A3,C1 --seed 7");
    cmd->require_subcommand(1);
    Command scene = add_puzzle_scene(*cmd);
    Command solve = add_puzzle_solve(*cmd);
    Command generate = add_puzzle_generate(*cmd);
    return [cmd, scene, solve, generate] {
        return cmd->got_subcommand("scene")      ? scene()
               : cmd->got_subcommand("generate") ? generate()
                                                 : solve();
    };
}

} // namespace orthoray::cli

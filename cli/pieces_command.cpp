// orthoray pieces FILE: print the 2D piece tables the engine steps through.
#include "commands.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/pieces.hpp"
#include "scene_format_option.hpp"
#include "stop_at_once.hpp"

#include <iostream>
#include <memory>
#include <sstream>

namespace orthoray::cli {

Command add_pieces(CLI::App& app) {
    auto file = std::make_shared<std::string>();
    auto format = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand(
        "pieces", "Print the 2D piece tables: for each mirror and each of the four diagonal\n"
                  "directions, the runs of positions that reach the same next mirror by the\n"
                  "same translation (the interval exchange of docs/piece-tables.md).\n"
                  "Coordinates are the scene's lattice coordinates (docs/lattice.md).\n\n"
                  "Example:\n"
                  "  orthoray pieces instances/2d/box-corner-3x5.scene");
    auto json = std::make_shared<bool>(false);
    cmd->add_option("FILE", *file, "a 2D scene whose ray moves in both x and y")->required();
    cmd->add_flag("--json", *json,
                  "one JSON object: the elements and every piece (docs/piece-tables.md); "
                  "axis-parallel scenes only");
    add_scene_format_option(cmd, *format);
    return [file, format, json] {
        // The tables are printed whole at the end: SIGINT and SIGTERM end the
        // command at once with exit 3 (stop_at_once.hpp), nothing printed.
        stop_at_once(std::nullopt);
        const Scene scene = load_scene(*file, scene_format_named(*format));
        if (*json && scene.has_diagonal())
            throw UsageError("found --json for a scene with diagonal elements, expected an "
                             "axis-parallel scene (the text form shows the map on the "
                             "eight-sheeted cover; 'orthoray exchange --json' exports it)");
        std::ostringstream out; // nothing reaches stdout unless the tables exist
        const bool available =
            write_piece_tables(scene, out, *json ? PieceTableFormat::json : PieceTableFormat::text)
                .available;
        if (!available && scene.has_diagonal())
            throw UsageError("found no piece tables for '" + *file +
                             "', expected a scene without one-sided elements whose ray reflects "
                             "at least once and whose tables fit the induction's cap (with "
                             "diagonal elements they are the first-return map on the "
                             "eight-sheeted cover: docs/induction.md, section 6)");
        if (!available)
            throw UsageError("found '" + *file +
                             "', expected a 2D scene whose ray moves in both x and y (piece "
                             "tables exist only for those)");
        stop_no_more(); // decided: a stop now would cut the printing short
        std::cout << out.str();
        return static_cast<int>(yes);
    };
}

} // namespace orthoray::cli

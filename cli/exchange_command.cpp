// orthoray exchange FILE: export the interval exchange the induction engine
// builds (docs/induction.md, "Exporting the exchange").
#include "commands.hpp"
#include "orthoray/exchange.hpp"
#include "orthoray/parse.hpp"
#include "scene_format_option.hpp"
#include "stop_at_once.hpp"

#include <iostream>
#include <memory>
#include <sstream>

namespace orthoray::cli {

Command add_exchange(CLI::App& app) {
    auto file = std::make_shared<std::string>();
    auto format = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    CLI::App* cmd = app.add_subcommand(
        "exchange",
        "Export the interval exchange of a 2D scene: the first-return map of its ray's\n"
        "states on the mirrors, a bijection of [0, N) translating each of k pieces, as\n"
        "the induction engine builds it. Written as the two rows of labels (domain\n"
        "order, image order) and the lengths that other interval-exchange software\n"
        "reads, with what happens on each piece (docs/induction.md).\n\n"
        "Example:\n"
        "  orthoray exchange instances/2d/box-corner-3x5.scene --json");
    cmd->add_option("FILE", *file,
                    "a 2D scene whose ray moves along neither axis and reflects at least once")
        ->required();
    cmd->add_flag("--json", *json, "one JSON object instead of the text form");
    add_scene_format_option(cmd, *format);
    return [file, format, json] {
        // The exchange is printed whole at the end: SIGINT and SIGTERM end the
        // command at once with exit 3 (stop_at_once.hpp), nothing printed.
        stop_at_once(std::nullopt);
        const Scene scene = load_scene(*file, scene_format_named(*format));
        const std::optional<IntervalExchange> exchange = exchange_of(scene);
        if (!exchange && scene.has_diagonal())
            throw UsageError("found no interval exchange for '" + *file +
                             "', expected a scene without one-sided elements whose ray reflects "
                             "at least once, whose tables fit the induction's cap, and where no "
                             "two states step to one (a collision: 'orthoray pieces' lists them; "
                             "docs/induction.md, section 6)");
        if (!exchange)
            throw UsageError("found no interval exchange for '" + *file +
                             "', expected a 2D scene without one-sided elements whose ray moves "
                             "along neither axis and reflects at least once, and whose tables "
                             "fit the induction's cap (docs/induction.md)");
        std::ostringstream out; // whole or nothing on stdout
        write_exchange(*exchange, out, *json ? ExchangeFormat::json : ExchangeFormat::text);
        stop_no_more(); // decided: a stop now would cut the printing short
        std::cout << out.str();
        return static_cast<int>(yes);
    };
}

} // namespace orthoray::cli

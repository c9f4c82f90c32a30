#include "app.hpp"

#include "man_page.hpp"

#include "orthoray/version.hpp"

#include <memory>
#include <sstream>
#include <string>

namespace orthoray::cli {
namespace {

// `orthoray --help` lists each subcommand with the first clause of its
// description only (man_page.hpp's summary); the full text, examples included, is the subcommand's
// own --help. CLI11 would print every line of every description (about 80
// lines for ten commands).
class OneLineSubcommands : public CLI::Formatter {
public:
    std::string make_subcommand(const CLI::App* sub) const override {
        std::ostringstream out;
        CLI::detail::format_help(out, sub->get_display_name(true), summary(sub->get_description()),
                                 column_width_);
        return out.str();
    }
};

} // namespace

std::vector<Subcommand> build_cli(CLI::App& app) {
    app.description(
        "orthoray: decides exactly where light goes among axis-aligned and diagonal\n"
        "mirrors, splitters and absorbers, and proves each answer with a certificate.\n\n"
        "Example:\n"
        "  orthoray solve instances/2d/box-corner-3x5.scene --certificate path.cert\n"
        "  orthoray verify instances/2d/box-corner-3x5.scene path.cert\n"
        "  orthoray generate box --sides 3 5 -o box.scene\n"
        "  orthoray bounds box.scene\n"
        "  orthoray batch instances/ -o results.jsonl\n\n"
        "Exit status: 0 yes (or valid), 1 no (or invalid), 2 bad input or usage,\n"
        "3 a resource limit (steps, time, memory) or SIGINT/SIGTERM stopped the run first,\n"
        "4 an internal error, 5 an output could not be written (full disk, closed pipe).\n"
        "Scene formats and rules: docs/scene-format.md, docs/scene-json.md,\n"
        "docs/grid-mazes.md (grid mirror mazes, .grid),\n"
        "docs/semantics.md. Pictures: docs/render.md. Each command's own help:\n"
        "orthoray COMMAND --help.");
    app.name("orthoray");
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("orthoray ") + orthoray::version);
    app.formatter(std::make_shared<OneLineSubcommands>());
    std::vector<Subcommand> commands;
    auto add = [&](Command (*registration)(CLI::App&)) {
        Command run = registration(app);
        commands.push_back({app.get_subcommands({}).back(), std::move(run)});
    };
    add(add_solve);
    add(add_verify);
    add(add_pieces);
    add(add_exchange);
    add(add_generate);
    add(add_bounds);
    add(add_render);
    add(add_convert);
    add(add_puzzle);
    add(add_realistic);
    add(add_batch);
    add(add_version);
    return commands;
}

} // namespace orthoray::cli

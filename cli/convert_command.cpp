// orthoray convert IN OUT: rewrite a scene, or a grid maze as its scene, as
// .scene text or as JSON.
#include "commands.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/scene.hpp"
#include "output_file.hpp"
#include "phase_progress.hpp"
#include "scene_format_option.hpp"
#include "stop_at_once.hpp"

#include <memory>
#include <optional>

namespace orthoray::cli {
namespace {

struct ConvertArgs {
    std::string in, out, from, to;
    double timeout = 0;
    bool quiet = false;
};

int run(const ConvertArgs& args, const CLI::Option* timeout) {
    stop_at_once(timeout->count() > 0 ? std::optional<double>(args.timeout) : std::nullopt);
    PhaseProgress progress("convert", !args.quiet);
    const SceneFormat to = resolve_scene_format(args.out, scene_format_named(args.to));
    if (to == SceneFormat::grid)
        throw UsageError("found OUT '" + args.out +
                         "', expected a name for a .scene or JSON scene, or --to scene|json (a "
                         "scene is not written back as a grid maze)");
    // Opened before the reading, which is the long part: a path that
    // cannot be written is refused at once.
    OutputFile out(args.out, {args.in}, "the scene");
    progress.phase("reading " + args.in);
    const Scene scene = load_scene(args.in, scene_format_named(args.from));
    const bool json = to == SceneFormat::json;
    progress.phase("writing " + args.out);
    const std::string text = json ? write_scene_json(scene) : write_scene(scene);
    // Decided: a stop from here on would cut the bytes short where the
    // target is written in place (/dev/stdout, a pipe), so the command finishes.
    stop_no_more();
    out.stream() << text;
    out.commit();
    progress.finish();
    return yes;
}

} // namespace

Command add_convert(CLI::App& app) {
    auto args = std::make_shared<ConvertArgs>();
    CLI::App* cmd = app.add_subcommand(
        "convert", "Convert a scene between the .scene text format and JSON, or a grid maze\n"
                   "to its scene; nothing is rounded (JSON rationals are strings). Grid\n"
                   "mirror mazes (.grid): docs/grid-mazes.md.\n\n"
                   "Example:\n"
                   "  orthoray convert instances/2d/box-corner-3x5.scene box.json\n"
                   "  orthoray convert box.json box.scene\n"
                   "  orthoray convert instances/grid/samsung-mirror-game-2.grid maze.scene\n\n"
                   "Exit status: 0 written, 2 bad input or usage, 3 stopped by --timeout,\n"
                   "SIGINT or SIGTERM (OUT untouched), 5 a failed write.");
    cmd->add_option("IN", args->in, "the scene to read")->required();
    cmd->add_option("OUT", args->out, "the file to write (replaced if it exists)")->required();
    add_scene_format_option(cmd, args->from, "--from", "IN");
    add_scene_format_option(cmd, args->to, "--to", "OUT", true);
    CLI::Option* timeout = add_timeout_option(cmd, args->timeout, "the conversion");
    cmd->add_flag("--quiet", args->quiet,
                  "no progress line (it is shown on long runs only when stderr is a terminal)");
    return [args, timeout] { return run(*args, timeout); };
}

} // namespace orthoray::cli

// orthoray convert IN OUT: rewrite a scene as .scene text or as JSON.
#include "commands.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/scene.hpp"
#include "scene_format_option.hpp"

#include <fstream>
#include <memory>

namespace orthoray::cli {
namespace {

struct ConvertArgs {
    std::string in, out, from, to;
};

int run(const ConvertArgs& args) {
    const Scene scene = load_scene(args.in, scene_format_named(args.from));
    const bool json =
        resolve_scene_format(args.out, scene_format_named(args.to)) == SceneFormat::json;
    const std::string text = json ? write_scene_json(scene) : write_scene(scene);
    std::ofstream out(args.out, std::ios::binary | std::ios::trunc);
    if (!out || !(out << text) || !out.flush())
        throw UsageError("cannot write the scene file '" + args.out + "'");
    return yes;
}

} // namespace

Command add_convert(CLI::App& app) {
    auto args = std::make_shared<ConvertArgs>();
    CLI::App* cmd = app.add_subcommand(
        "convert", "Convert a scene between the .scene text format and JSON; nothing is\n"
                   "rounded (JSON rationals are strings).\n\n"
                   "Example:\n"
                   "  orthoray convert instances/2d/box-corner-3x5.scene box.json\n"
                   "  orthoray convert box.json box.scene\n\n"
                   "Exit status: 0 written, 2 bad input or usage.");
    cmd->add_option("IN", args->in, "the scene to read")->required();
    cmd->add_option("OUT", args->out, "the file to write (replaced if it exists)")->required();
    add_scene_format_option(cmd, args->from, "--from", "IN");
    add_scene_format_option(cmd, args->to, "--to", "OUT");
    return [args] { return run(*args); };
}

} // namespace orthoray::cli

// The --format option every command that reads a scene offers.
#pragma once

#include "option_checks.hpp"
#include "orthoray/parse.hpp"

#include <CLI/CLI.hpp>

#include <map>
#include <string>

namespace orthoray::cli {

inline const std::map<std::string, SceneFormat>& scene_formats() {
    static const std::map<std::string, SceneFormat> formats{{"auto", SceneFormat::automatic},
                                                            {"scene", SceneFormat::text},
                                                            {"json", SceneFormat::json},
                                                            {"grid", SceneFormat::grid}};
    return formats;
}

// Adds `--format auto|scene|json|grid` (or another option name) storing into
// `format`. An output's option (`writing`) leaves out grid: a scene is not
// written back as a maze.
inline CLI::Option* add_scene_format_option(CLI::App* cmd, std::string& format,
                                            const std::string& name = "--format",
                                            const std::string& what = "the scene file",
                                            bool writing = false) {
    format = "auto";
    if (writing)
        return cmd
            ->add_option(
                name, format,
                "format of " + what +
                    ": auto (default: JSON when the name ends in .json, .scene text "
                    "otherwise), scene (docs/scene-format.md) or json (docs/scene-json.md)")
            ->check(one_of({"auto", "scene", "json"}));
    return cmd
        ->add_option(name, format,
                     "format of " + what +
                         ": auto (default: JSON when the name ends in .json, a grid maze when it "
                         "ends in .grid, .scene text otherwise), scene (docs/scene-format.md), "
                         "json (docs/scene-json.md) or grid (docs/grid-mazes.md)")
        ->check(one_of({"auto", "scene", "json", "grid"}));
}

inline SceneFormat scene_format_named(const std::string& name) {
    return scene_formats().at(name);
}

} // namespace orthoray::cli

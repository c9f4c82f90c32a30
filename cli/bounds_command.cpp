// orthoray bounds FILE: the state-count bounds of a scene (docs/bounds.md).
#include "commands.hpp"
#include "orthoray/bounds.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/scene.hpp"
#include "phase_progress.hpp"
#include "scene_format_option.hpp"
#include "stop_at_once.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace orthoray::cli {
namespace {

struct BoundsArgs {
    std::string file, format;
    bool json = false, no_pieces = false, quiet = false;
    double timeout = 0;
};

// Lattice axes, named after the scene axes they scale.
std::string scale_text(const StateBounds& b) {
    std::string text;
    for (int i = 0; i < b.dim; ++i)
        text += std::string(i ? ", " : "") + axis_name(b.active[static_cast<std::size_t>(i)]) +
                " * " + b.scale[static_cast<std::size_t>(i)].get_str();
    return text;
}

std::string moduli_text(const StateBounds& b) {
    if (b.octagonal) return "N = " + b.line_modulus[0].get_str() + " (cross(w, P) = 0 mod N)";
    if (b.dim < 2) return "none (the ray moves on one axis)";
    if (b.dim == 2) return "G = " + b.line_modulus[0].get_str();
    return "G_xy = " + b.line_modulus[0].get_str() + ", G_xz = " + b.line_modulus[1].get_str() +
           ", G_yz = " + b.line_modulus[2].get_str();
}

// Big integers are JSON numbers written from their decimal text, exact
// however large (as `solve --json` writes reflections).
void print_json(const StateBounds& b) {
    std::cout << "{\"dim\":" << b.dim << ",\"scale\":[";
    for (int i = 0; i < b.dim; ++i)
        std::cout << (i ? "," : "") << b.scale[static_cast<std::size_t>(i)].get_str();
    std::cout << "],\"octagonal\":" << (b.octagonal ? "true" : "false")
              << ",\"directions\":" << b.directions << ",\"rays\":" << b.rays
              << ",\"elements\":" << b.elements << ",\"input_bits\":" << b.input_bits
              << ",\"magnitude_bits\":" << b.magnitude_bits << ",\"state_bits\":" << b.state_bits
              << ",\"points\":" << b.points.get_str()
              << ",\"lattice_states\":" << b.lattice_states.get_str() << ",\"line_modulus\":[";
    const int pairs = b.dim * (b.dim - 1) / 2;
    for (int p = 0; p < pairs; ++p)
        std::cout << (p ? "," : "") << b.line_modulus[static_cast<std::size_t>(p)].get_str();
    std::cout << "],\"refined_states\":" << b.refined_states.get_str();
    if (b.pieces) std::cout << ",\"pieces\":" << *b.pieces;
    std::cout << "}\n";
}

void print_text(const StateBounds& b) {
    std::printf("active axes      %d\n", b.dim);
    std::printf("lattice scale    %s\n", scale_text(b).c_str());
    std::printf("elements         %zu (that the ray can meet)\n", b.elements);
    std::printf("input bits       %zu\n", b.input_bits);
    std::printf("magnitude bits   %zu (largest |lattice coordinate|)\n", b.magnitude_bits);
    std::printf("state bits       %zu\n", b.state_bits);
    std::printf("lattice points   %s (on the elements, each once)\n", b.points.get_str().c_str());
    if (b.octagonal)
        std::printf("lattice states   %s (points * %u directions)\n",
                    b.lattice_states.get_str().c_str(), b.directions);
    else
        std::printf("lattice states   %s (points * 2^%d)\n", b.lattice_states.get_str().c_str(),
                    b.dim);
    if (b.rays > 1)
        std::printf("rays             %zu (points and states summed over their lattices)\n",
                    b.rays);
    std::printf("line modulus     %s\n", moduli_text(b).c_str());
    std::printf("refined states   %s\n", b.refined_states.get_str().c_str());
    if (b.pieces) std::printf("piece tables     %zu pieces\n", *b.pieces);
}

} // namespace

Command add_bounds(CLI::App& app) {
    auto args = std::make_shared<BoundsArgs>();
    CLI::App* cmd = app.add_subcommand(
        "bounds",
        "Print the bounds on the states a trajectory can visit (docs/bounds.md): the lattice\n"
        "scale, bit sizes, the lattice bound (integer points on the elements times the 2^M\n"
        "directions; an unanswered trajectory must cycle within it), the refined bound that\n"
        "also keeps the invariant of the ray's unfolded line, and in 2D the piece-table size.\n\n"
        "Example:\n"
        "  orthoray bounds instances/2d/box-corner-3x5.scene --json\n"
        "  {\"dim\":2,\"scale\":[1,1],...,\"lattice_states\":64,...,\"refined_states\":32,...}");
    cmd->add_option("FILE", args->file, "the scene (.scene text or .json)")->required();
    add_scene_format_option(cmd, args->format);
    cmd->add_flag("--json", args->json, "print one JSON object (big integers exact)");
    cmd->add_flag("--no-pieces", args->no_pieces, "do not build the 2D piece tables");
    CLI::Option* timeout = add_timeout_option(cmd, args->timeout, "the computation");
    cmd->add_flag("--quiet", args->quiet,
                  "no progress line (it is shown on long runs only when stderr is a terminal)");
    return [args, timeout] {
        stop_at_once(timeout->count() > 0 ? std::optional<double>(args->timeout) : std::nullopt);
        PhaseProgress progress("bounds", !args->quiet);
        progress.phase("reading " + args->file);
        const Scene scene = load_scene(args->file, scene_format_named(args->format));
        progress.phase("computing the bounds");
        const StateBounds b = compute_bounds(scene, !args->no_pieces);
        progress.finish();
        stop_no_more(); // decided: a stop now would cut the printing short
        if (args->json)
            print_json(b);
        else
            print_text(b);
        return static_cast<int>(yes);
    };
}

} // namespace orthoray::cli

// orthoray realistic FILE: the intensity question of a realistic model
// (docs/realistic-scenes.md), decided by the pair dynamic program.
#include "commands.hpp"
#include "option_checks.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/realistic.hpp"
#include "output_file.hpp"
#include "scene_checks.hpp"
#include "stop_at_once.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

namespace orthoray::cli {
namespace {

struct RealisticArgs {
    std::string file, certificate, min_intensity = "0", write_model;
    bool json = false, from_scene = false;
    std::size_t target = 1, max_states = 1'000'000;
    double timeout = 0;
};

// The usage errors of the options' combinations, before any output is
// opened and any work done.
void check_usage(const RealisticArgs& args) {
    if (!args.from_scene) {
        if (!args.write_model.empty())
            throw UsageError("found --write-model without --from-scene, expected --from-scene");
        return;
    }
    if (!args.certificate.empty() && args.write_model.empty())
        throw UsageError("found --certificate with --from-scene, expected --write-model too (a "
                         "certificate is checked against a model file)");
    if (args.min_intensity.empty() ||
        args.min_intensity.find_first_not_of("0123456789") != std::string::npos)
        throw UsageError("found --min-intensity " + args.min_intensity +
                         ", expected a natural number (0, 1, 2, ...)");
    refuse_same_output(args.write_model, "the model", args.certificate, "the certificate");
}

// The model to decide: the file itself, or the one derived from a scene.
RealisticModel model_of(const RealisticArgs& args) {
    if (!args.from_scene) return read_realistic(read_file(args.file), args.file);
    const Scene scene = load_scene(args.file);
    require_one_intense_ray(scene, args.file);
    if (args.target == 0 || args.target > scene.targets.size())
        throw UsageError("found --target " + std::to_string(args.target) +
                         ", expected a target of the scene (1 to " +
                         std::to_string(scene.targets.size()) + ")");
    return realistic_model_of_scene(scene, args.target - 1, Integer(args.min_intensity, 10),
                                    args.max_states);
}

int run(const RealisticArgs& args, bool timed) {
    // Files are renamed into place whole and the answer printed at the end:
    // SIGINT, SIGTERM and --timeout end the command at once with exit 3
    // (stop_at_once.hpp), nothing written, until the outputs are complete.
    stop_at_once(timed ? std::optional<double>(args.timeout) : std::nullopt);
    check_usage(args);
    // Opened before any work, so that a path that cannot be written is
    // refused at once; written at the end, and renamed into place together.
    std::optional<OutputFile> model_file, certificate_file;
    if (!args.write_model.empty())
        model_file.emplace(args.write_model, std::vector{args.file}, "the model");
    if (!args.certificate.empty())
        certificate_file.emplace(args.certificate, std::vector{args.file}, "the certificate");
    // The time counts the derivation too: from a scene it is most of it.
    const auto begin = std::chrono::steady_clock::now();
    RealisticModel model;
    try {
        model = model_of(args);
    } catch (const StatesExceeded& e) {
        // A limit, like --max-steps: the scene is fine, and nothing is
        // proven about it yet (the model is not complete, so not written).
        std::fprintf(stderr, "orthoray: stopped: %s (--max-states %zu); no answer\n", e.what(),
                     e.max_states());
        return limit;
    }
    const RealisticAnswer answer = solve_realistic(model);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    // The answer is decided: a stop from here on would leave one file in
    // place and the other not, or cut short one written in place (/dev/stdout).
    stop_no_more();
    if (model_file) model_file->stream() << write_realistic(model);
    if (certificate_file) write_realistic_certificate(certificate_file->stream(), model, answer);
    if (model_file) model_file->commit();
    if (certificate_file) certificate_file->commit();
    if (args.json) {
        std::cout << "{\"answer\":" << (answer.yes ? "\"yes\"" : "\"no\"")
                  << ",\"best\":" << (answer.best < 0 ? std::string("null") : answer.best.get_str())
                  << ",\"eps\":" << model.eps.get_str() << ",\"path\":[";
        for (std::size_t k = 0; k < answer.path.size(); ++k)
            std::cout << (k ? "," : "") << nlohmann::json(model.objects[answer.path[k]]).dump();
        std::cout << "],\"arrivals\":[";
        for (std::size_t k = 0; k < answer.intensities.size(); ++k)
            std::cout << (k ? "," : "") << answer.intensities[k].get_str();
        std::cout << "],\"pairs\":" << answer.bounds.size()
                  << ",\"seconds\":" << nlohmann::json(seconds).dump() << "}\n";
    } else {
        std::printf("answer       %s\n", answer.yes ? "yes" : "no");
        std::printf("best         %s (eps %s)\n",
                    answer.best < 0 ? "none arrives" : answer.best.get_str().c_str(),
                    model.eps.get_str().c_str());
        if (!answer.path.empty()) {
            std::string path, arrivals;
            for (const std::size_t object : answer.path) path += ' ' + model.objects[object];
            for (const Integer& i : answer.intensities) arrivals += ' ' + i.get_str();
            std::printf("path        %s\n", path.c_str());
            std::printf("arrivals    %s\n", arrivals.c_str());
        }
        std::printf("pairs        %zu\n", answer.bounds.size());
        std::printf("time         %.3f ms\n", seconds * 1e3);
    }
    return answer.yes ? yes : no;
}

} // namespace

Command add_realistic(CLI::App& app) {
    auto args = std::make_shared<RealisticArgs>();
    CLI::App* cmd = app.add_subcommand(
        "realistic",
        "Does some ray path from the source object reach the receiver with intensity above\n"
        "eps? Realistic scenes (Isobe et al. 2005): intensities in N never grow along a path,\n"
        "each object passes on a monotone share; decided by a dynamic program over object\n"
        "pairs (docs/realistic-scenes.md).\n\n"
        "Example:\n"
        "  orthoray realistic instances/realistic/greedy-fails.realistic\n\n"
        "Exit status: 0 yes, 1 no, 2 bad input or usage, 3 stopped (--max-states,\n"
        "--timeout, a signal), 5 the certificate could not be written.\n"
        "'orthoray verify MODEL.realistic CERT' checks a certificate.");
    cmd->add_option("FILE", args->file,
                    "the model (docs/realistic-scenes.md), or a scene with --from-scene")
        ->required();
    cmd->add_flag("--json", args->json,
                  "one JSON object: answer, best (null when nothing arrives), eps, path, "
                  "arrivals, pairs, seconds");
    CLI::Option* from_scene = cmd->add_flag(
        "--from-scene", args->from_scene,
        "FILE is a mirror scene with one ray carrying an intensity: decide the model "
        "derived from its lattice states (docs/realistic-scenes.md, \"From mirror "
        "scenes\"); objects S (the ray), R (the target) and e1, e2, ... (the elements)");
    cmd->add_option("--min-intensity", args->min_intensity,
                    "with --from-scene: eps, a natural number (default 0)")
        ->check(not_empty("a natural number"))
        ->needs(from_scene); // a model states its own eps
    cmd->add_option("--target", args->target,
                    "with --from-scene: which target is the receiver (default 1)")
        ->transform(whole_number_u64())
        ->needs(from_scene);
    cmd->add_option("--max-states", args->max_states,
                    "with --from-scene: the most states leaving junctions (where the ray "
                    "may split) the derivation keeps; past them it stops, exit 3 (default "
                    "1000000, at most 4294967294)")
        ->transform(whole_number_in(1, max_kept_states))
        ->needs(from_scene);
    cmd->add_option("--write-model", args->write_model,
                    "with --from-scene: write the derived model to this file (then --certificate "
                    "can be checked against it with 'orthoray verify')")
        ->check(not_empty("a file name"));
    cmd->add_option("--certificate", args->certificate,
                    "write the path and the closed pair bounds to this file")
        ->check(not_empty("a file name"));
    const CLI::Option* timeout = add_timeout_option(cmd, args->timeout, "the command");
    return [args, timeout] { return run(*args, timeout->count() > 0); };
}

} // namespace orthoray::cli

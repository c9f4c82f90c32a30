// orthoray verify FILE CERT: check a certificate independently of the solvers.
#include "commands.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/realistic.hpp"
#include "scene_format_option.hpp"
#include "stop_at_once.hpp"

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace orthoray::cli {
namespace {

struct VerifyArgs {
    std::string file, certificate, format;
    bool json = false;
    double timeout = 0;
};

// The verdict as text ("valid: hit, 6 reflections") or one JSON object
// {"valid": ..., "message": ...}; the exit status says the same.
int report(const VerifyArgs& args, bool valid, const std::string& message) {
    stop_no_more(); // decided: a stop now would cut the printing short
    if (args.json)
        std::cout << nlohmann::json{{"valid", valid}, {"message", message}}.dump() << '\n';
    else
        std::cout << message << '\n';
    return valid ? yes : no;
}

bool is_realistic_model(const std::string& path) {
    const std::string ending = ".realistic";
    return path.size() >= ending.size() &&
           path.compare(path.size() - ending.size(), ending.size(), ending) == 0;
}

int run(const VerifyArgs& args, bool timed) {
    // The verdict is printed at the end. A check takes time in proportion
    // to the reflections its stretches and witnesses hold, which nothing in
    // a certificate bounds: SIGINT, SIGTERM and --timeout end it at once
    // with exit 3 (stop_at_once.hpp), no verdict printed.
    stop_at_once(timed ? std::optional<double>(args.timeout) : std::nullopt);
    if (is_realistic_model(args.file)) {
        const RealisticModel model = read_realistic(read_file(args.file), args.file);
        const std::unique_ptr<std::istream> cert = open_file_stream(args.certificate);
        const RealisticVerdict verdict =
            verify_realistic_certificate(model, *cert, args.certificate);
        return report(args, verdict.valid, verdict.message);
    }
    const Scene scene = load_scene(args.file, scene_format_named(args.format));
    const std::unique_ptr<std::istream> cert = open_file_stream(args.certificate);
    const Verdict verdict = verify_certificate(scene, *cert, args.certificate);
    return report(args, verdict.valid, verdict.message);
}

} // namespace

Command add_verify(CLI::App& app) {
    auto args = std::make_shared<VerifyArgs>();
    CLI::App* cmd = app.add_subcommand(
        "verify", "Check a certificate written by 'orthoray solve --certificate'.\n\n"
                  "The check is plain rational geometry that shares no code with the solvers.\n"
                  "Example:\n"
                  "  orthoray verify instances/2d/box-corner-3x5.scene path.cert\n"
                  "  valid: hit, 6 reflections\n\n"
                  "Exit status: 0 valid, 1 invalid (the first failing step is printed),\n"
                  "2 unreadable or malformed scene or certificate, 3 stopped (--timeout,\n"
                  "SIGINT or SIGTERM) before a verdict.");
    cmd->add_option("FILE", args->file,
                    "the scene (.scene text or JSON), or a realistic model (.realistic, checked "
                    "against 'orthoray realistic --certificate')")
        ->required();
    cmd->add_option("CERT", args->certificate, "the certificate file")->required();
    add_scene_format_option(cmd, args->format);
    cmd->add_flag("--json", args->json,
                  "print one JSON object: valid (true or false) and message (the text verdict)");
    const CLI::Option* timeout = add_timeout_option(cmd, args->timeout, "the check");
    return [args, timeout] { return run(*args, timeout->count() > 0); };
}

} // namespace orthoray::cli

// orthoray solve FILE: decide an instance and print the answer.
#include "commands.hpp"
#include "option_checks.hpp"
#include "orthoray/answer_json.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "output_file.hpp"
#include "run_monitor.hpp"
#include "scene_checks.hpp"
#include "scene_format_option.hpp"
#include "solve_choices.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <vector>

namespace orthoray::cli {
namespace {

struct SolveArgs {
    std::string file, certificate, format, certificate_format = "text";
    bool json = false, quiet = false;
    SolveChoices choices;
};

// The illumination question's lines of the summary: one a target.
void print_targets_text(const Answer& a) {
    for (std::size_t t = 0; t < a.targets.size(); ++t) {
        const TargetAnswer& target = a.targets[t];
        if (target.status == TargetAnswer::Status::lit)
            std::printf("target %zu  lit after %s reflections by ray %zu%s%s%s\n", t + 1,
                        target.reflections.get_str().c_str(), target.ray,
                        target.intensity ? " with intensity " : "",
                        target.intensity ? target.intensity->get_str().c_str() : "",
                        target.best_proven ? "" : " (the best so far: the run stopped first)");
        else
            std::printf("target %zu  %s\n", t + 1,
                        target.status == TargetAnswer::Status::unlit ? "unlit" : "unknown");
    }
}

// Why a run stopped, in the words of the option that set the limit.
const char* limit_note(Limit limit) {
    switch (limit) {
    case Limit::steps:
        return " (--max-steps reached)";
    case Limit::time:
        return " (--timeout reached)";
    case Limit::memory:
        return " (out of memory)";
    case Limit::interrupt:
        return " (interrupted)";
    }
    return "";
}

void print_text(const Answer& a, const std::string& engine, double seconds) {
    print_targets_text(a);
    std::printf("answer       %s\n", answer_word(a));
    std::printf("reason       %s%s\n", to_string(a.reason),
                a.reason == Reason::limit ? limit_note(a.limit) : "");
    if (a.reason == Reason::cycle && a.tail != 0)
        std::printf("tail         %s\n", a.tail.get_str().c_str());
    if (a.illumination())
        std::printf("states       %s%s\n", a.states.get_str().c_str(),
                    a.states_lower_bound ? " (at least)" : "");
    else
        std::printf("%-12s %s\n", a.reason == Reason::cycle ? "period" : "reflections",
                    (a.reason == Reason::cycle ? a.period() : a.reflections).get_str().c_str());
    std::printf("engine       %s (%s%s%s)\n", engine.c_str(), to_string(a.arithmetic),
                a.shooter == ShooterUsed::none ? "" : ", ", to_string(a.shooter));
    if (a.engine == EngineUsed::induction)
        std::printf("induction    %llu steps on %zu pieces, %s states\n",
                    static_cast<unsigned long long>(a.stats.induction.steps),
                    a.stats.induction.pieces, a.stats.induction.states.get_str().c_str());
    std::printf("time         %.3f ms\n", seconds * 1e3);
}

double seconds_since(std::chrono::steady_clock::time_point begin) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

// What the run reports when it stopped before an engine could say how far
// it got (memory ran out or a signal came while reading the scene): no
// engine ran, no reflections, and no arithmetic chosen yet.
Answer stopped_before_solving(Limit limit) {
    Answer answer;
    answer.limit = limit;
    return answer;
}

int run(const SolveArgs& args, const CLI::Option* certificate) {
    const auto begin_command = std::chrono::steady_clock::now();
    args.choices.check();
    if (certificate->count() > 0 && args.choices.engine == "graph")
        throw UsageError("found --engine graph with --certificate, expected another engine "
                         "(the graph engine writes no certificate)");
    if (args.choices.max_memory > 0) limit_memory(args.choices.max_memory);
    // From here on SIGINT and SIGTERM end the run with the usual output.
    const InterruptGuard interrupts;
    auto report = [&](const Answer& answer, double seconds) {
        const std::string engine = engine_name(answer, args.choices.engine);
        if (args.json)
            std::cout << '{' << answer_json_members(answer, engine, seconds) << "}\n";
        else
            print_text(answer, engine, seconds);
        if (!answer.decided()) return limit;
        return answer.yes() ? yes : no;
    };
    const std::optional<std::chrono::steady_clock::time_point> deadline =
        args.choices.deadline(begin_command);
    auto past_deadline = [&] { return deadline && std::chrono::steady_clock::now() >= *deadline; };
    Scene scene;
    try {
        // Parsing huge numbers takes a while: a signal or the deadline stops
        // it between numbers, with nothing proven yet.
        const ReadStopCheck stop_check(
            args.file, [&] { return InterruptGuard::requested() || past_deadline(); });
        scene =
            load_scene(args.file,
                       scene_format_named(args.format)); // bad input ends here, before any output
    } catch (const std::bad_alloc&) {
        return report(stopped_before_solving(Limit::memory), seconds_since(begin_command));
    } catch (const ReadInterrupted&) {
        // The time is the reading's: what the run spent before the stop.
        return report(stopped_before_solving(InterruptGuard::requested() || !past_deadline()
                                                 ? Limit::interrupt
                                                 : Limit::time),
                      seconds_since(begin_command));
    }
    // The reference illumination search keeps every state and proves
    // nothing: it writes no certificate. (The intensity search with the
    // reference scan is the same search as without it, and writes one.)
    if (certificate->count() > 0 && args.choices.engine == "reference" &&
        !scene.single_trajectory() && args.choices.min_intensity.empty())
        throw UsageError("found --engine reference with --certificate for the illumination "
                         "question, expected another engine (the reference illumination search "
                         "writes no certificate)");
    SolveOptions options = args.choices.options();
    if (options.min_intensity) require_intensities(scene, args.file);
    SolveMonitor monitor(scene, deadline, !args.quiet && options.engine != Engine::graph,
                         scene.single_trajectory() ? "reflections" : "branch states");
    options.monitor = &monitor;

    std::optional<OutputFile> cert_file;
    std::unique_ptr<CertificateWriter> writer;
    if (certificate->count() > 0) {
        cert_file.emplace(args.certificate, std::vector<std::string>{args.file}, "the certificate");
        writer = std::make_unique<CertificateWriter>(cert_file->stream(), scene,
                                                     args.certificate_format == "jsonl"
                                                         ? CertificateFormat::jsonl
                                                         : CertificateFormat::text);
        writer->attach(options);
    }
    auto begin = std::chrono::steady_clock::now();
    Answer answer;
    try {
        answer = solve(scene, options);
    } catch (const std::bad_alloc&) {
        answer = stopped_before_solving(Limit::memory);
    }
    double seconds = seconds_since(begin);
    monitor.erase_progress();
    // A limit, an interrupt included, still ends the certificate properly:
    // `partial` and `end` after the last complete point.
    // The certificate is renamed into place only once complete (a limit's
    // partial certificate is complete too: it says `partial`).
    if (writer) {
        writer->finish(answer);
        cert_file->commit();
    }
    return report(answer, seconds);
}

} // namespace

Command add_solve(CLI::App& app) {
    auto args = std::make_shared<SolveArgs>();
    CLI::App* cmd = app.add_subcommand(
        "solve", "Decide whether the ray reaches the target.\n\n"
                 "Example:\n"
                 "  orthoray solve instances/2d/box-corner-3x5.scene --json\n"
                 "  {\"answer\":\"yes\",\"reason\":\"hit\",\"reflections\":6,...}\n\n"
                 "answer yes: the ray reaches the target (reason hit) after `reflections`\n"
                 "reflections; answer no: it escapes to infinity, is absorbed, or is periodic\n"
                 "(reason cycle; `period` reflections per period) without passing the target.\n"
                 "Exit status: 0 yes, 1 no, 2 bad input or usage, 3 a limit (--max-steps,\n"
                 "--timeout, --max-memory, SIGINT or SIGTERM) stopped the run first, 5 the\n"
                 "certificate or the answer could not be written (docs/limits.md).");
    cmd->add_option("FILE", args->file,
                    "the scene: .scene text (docs/scene-format.md) or JSON (docs/scene-json.md)")
        ->required();
    add_scene_format_option(cmd, args->format);
    cmd->add_flag("--json", args->json,
                  "print one JSON object: answer, reason, reflections, period (cycles), "
                  "engine, arithmetic, seconds");
    CLI::Option* certificate =
        cmd->add_option("--certificate", args->certificate,
                        "stream the certificate (docs/certificates.md) to this file; check it "
                        "with 'orthoray verify'")
            ->check(not_empty("a file name"));
    // A format without a file would be silently ignored.
    cmd->add_option("--certificate-format", args->certificate_format,
                    "text (default) or jsonl: JSON Lines, one JSON object a line, for other "
                    "tools; 'verify' and 'render' read both (docs/certificates.md)")
        ->check(one_of({"text", "jsonl"}))
        ->needs(certificate);
    add_solve_choices(cmd, args->choices,
                      "let the process grow by at most MB megabytes of address space; running "
                      "out answers unknown (reason limit, limit memory), exit 3");
    cmd->add_flag("--quiet", args->quiet,
                  "no progress line (it is shown on long runs only when stderr is a terminal)");
    return [args, certificate] { return run(*args, certificate); };
}

} // namespace orthoray::cli

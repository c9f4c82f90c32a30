// orthoray solve FILE: decide an instance and print the answer.
#include "commands.hpp"
#include "option_checks.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "output_file.hpp"
#include "run_monitor.hpp"
#include "scene_format_option.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <vector>

namespace orthoray::cli {
namespace {

struct SolveArgs {
    std::string file, certificate, format, certificate_format = "text";
    bool json = false, quiet = false;
    std::uint64_t max_steps = 0, max_memory = 0;
    double timeout = 0;
    std::string engine = "auto", detector = "first-state", arithmetic = "auto", shooter = "auto";
};

const std::map<std::string, Engine> engines{{"auto", Engine::automatic},
                                            {"lattice", Engine::lattice},
                                            {"induction", Engine::induction},
                                            {"reference", Engine::reference},
                                            {"graph", Engine::graph}};
const std::map<std::string, CycleDetector> detectors{{"first-state", CycleDetector::first_state},
                                                     {"brent", CycleDetector::brent}};
const std::map<std::string, Arithmetic> arithmetics{
    {"auto", Arithmetic::automatic}, {"int128", Arithmetic::int128}, {"wide", Arithmetic::wide}};

const std::map<std::string, Shooter> shooters{{"auto", Shooter::automatic},
                                              {"grid", Shooter::grid},
                                              {"bvh", Shooter::bvh},
                                              {"pieces", Shooter::pieces},
                                              {"section", Shooter::section}};

template <class T>
std::vector<std::string> names(const std::map<std::string, T>& choices) {
    std::vector<std::string> out;
    for (const auto& [name, value] : choices) out.push_back(name);
    return out;
}

// The illumination question's part of the JSON object: one entry per target
// in file order (docs/optics.md), then the states explored.
void print_targets_json(const Answer& a) {
    std::cout << ",\"targets\":[";
    for (std::size_t t = 0; t < a.targets.size(); ++t) {
        const TargetAnswer& target = a.targets[t];
        std::cout << (t ? "," : "") << "{\"target\":" << t + 1 << ",\"answer\":";
        switch (target.status) {
        case TargetAnswer::Status::lit:
            std::cout << "\"yes\",\"reflections\":" << target.reflections.get_str()
                      << ",\"ray\":" << target.ray << "}";
            break;
        case TargetAnswer::Status::unlit:
            std::cout << "\"no\"}";
            break;
        case TargetAnswer::Status::unknown:
            std::cout << "\"unknown\"}";
            break;
        }
    }
    std::cout << "],\"states\":" << a.states.get_str();
}

// The illumination question's lines of the summary: one a target.
void print_targets_text(const Answer& a) {
    for (std::size_t t = 0; t < a.targets.size(); ++t) {
        const TargetAnswer& target = a.targets[t];
        if (target.status == TargetAnswer::Status::lit)
            std::printf("target %zu  lit after %s reflections by ray %zu\n", t + 1,
                        target.reflections.get_str().c_str(), target.ray);
        else
            std::printf("target %zu  %s\n", t + 1,
                        target.status == TargetAnswer::Status::unlit ? "unlit" : "unknown");
    }
}

// The engine a report names: the one that ran, or when none did (memory ran
// out first) the one asked for.
const char* engine_name(const Answer& a, const std::string& asked) {
    return a.engine == EngineUsed::none ? asked.c_str() : to_string(a.engine);
}

// One JSON object. `reflections` and `period` are written as JSON integers
// from their decimal text, so they are exact however large.
void print_json(const Answer& a, const char* engine, double seconds) {
    std::string reflections = a.reflections.get_str();
    std::cout << "{\"answer\":" << nlohmann::json(answer_word(a)).dump()
              << ",\"reason\":" << nlohmann::json(to_string(a.reason)).dump();
    if (a.reason == Reason::limit)
        std::cout << ",\"limit\":" << nlohmann::json(to_string(a.limit)).dump();
    std::cout << ",\"reflections\":" << reflections;
    if (a.reason == Reason::cycle)
        std::cout << ",\"tail\":" << a.tail.get_str() << ",\"period\":" << a.period().get_str();
    if (a.illumination()) print_targets_json(a);
    const Answer::Stats& stats = a.stats;
    std::cout << ",\"engine\":" << nlohmann::json(engine).dump()
              << ",\"arithmetic\":" << nlohmann::json(to_string(a.arithmetic)).dump();
    if (a.shooter != ShooterUsed::none)
        std::cout << ",\"shooter\":" << nlohmann::json(to_string(a.shooter)).dump()
                  << ",\"setup_seconds\":" << nlohmann::json(stats.setup.seconds).dump()
                  << ",\"grid_cells\":" << stats.setup.cells
                  << ",\"pieces\":" << stats.setup.pieces;
    if (a.engine == EngineUsed::induction)
        std::cout << ",\"exchange_pieces\":" << stats.induction.pieces
                  << ",\"exchange_states\":" << stats.induction.states.get_str()
                  << ",\"induction_steps\":" << stats.induction.steps
                  << ",\"induction_rounds\":" << stats.induction.rounds
                  << ",\"induction_seconds\":" << nlohmann::json(stats.induction.seconds).dump();
    std::cout << ",\"seconds\":" << nlohmann::json(seconds).dump() << "}\n";
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

void print_text(const Answer& a, const char* engine, double seconds) {
    print_targets_text(a);
    std::printf("answer       %s\n", answer_word(a));
    std::printf("reason       %s%s\n", to_string(a.reason),
                a.reason == Reason::limit ? limit_note(a.limit) : "");
    if (a.reason == Reason::cycle && a.tail != 0)
        std::printf("tail         %s\n", a.tail.get_str().c_str());
    if (a.illumination())
        std::printf("states       %s\n", a.states.get_str().c_str());
    else
        std::printf("%-12s %s\n", a.reason == Reason::cycle ? "period" : "reflections",
                    (a.reason == Reason::cycle ? a.period() : a.reflections).get_str().c_str());
    std::printf("engine       %s (%s%s%s)\n", engine, to_string(a.arithmetic),
                a.shooter == ShooterUsed::none ? "" : ", ", to_string(a.shooter));
    if (a.engine == EngineUsed::induction)
        std::printf("induction    %llu steps on %zu pieces, %s states\n",
                    static_cast<unsigned long long>(a.stats.induction.steps),
                    a.stats.induction.pieces, a.stats.induction.states.get_str().c_str());
    std::printf("time         %.3f ms\n", seconds * 1e3);
}

// What the run reports when it stopped before an engine could say how far
// it got (memory ran out or a signal came while reading the scene): no
// engine ran, no reflections, and no arithmetic chosen yet.
Answer stopped_before_solving(Limit limit) {
    Answer answer;
    answer.limit = limit;
    return answer;
}

// Certificates do not cover single trajectories with one-sided elements yet
// (docs/optics.md): refuse before any file is written.
void refuse_unsupported_certificate(const Scene& scene, const SolveArgs& args) {
    if (args.certificate.empty() || !scene.single_trajectory() || !scene.has_one_sided()) return;
    throw UsageError("--certificate: certificates for single trajectories with one-sided "
                     "elements are not supported yet");
}

int run(const SolveArgs& args, const CLI::Option* max_steps, const CLI::Option* certificate) {
    const auto begin_command = std::chrono::steady_clock::now();
    if (certificate->count() > 0 && args.engine == "graph")
        throw UsageError("found --engine graph with --certificate, expected another engine "
                         "(the graph engine writes no certificate)");
    if (args.max_memory > 0) limit_memory(args.max_memory);
    // From here on SIGINT and SIGTERM end the run with the usual output.
    const InterruptGuard interrupts;
    auto report = [&](const Answer& answer, double seconds) {
        if (args.json)
            print_json(answer, engine_name(answer, args.engine), seconds);
        else
            print_text(answer, engine_name(answer, args.engine), seconds);
        if (!answer.decided()) return limit;
        return answer.yes() ? yes : no;
    };
    std::optional<std::chrono::steady_clock::time_point> deadline;
    if (args.timeout > 0)
        deadline = begin_command + std::chrono::duration_cast<std::chrono::nanoseconds>(
                                       std::chrono::duration<double>(args.timeout));
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
        return report(stopped_before_solving(Limit::memory), 0);
    } catch (const ReadInterrupted&) {
        return report(stopped_before_solving(InterruptGuard::requested() || !past_deadline()
                                                 ? Limit::interrupt
                                                 : Limit::time),
                      0);
    }
    refuse_unsupported_certificate(scene, args);
    SolveOptions options;
    options.engine = engines.at(args.engine);
    options.cycle_detector = detectors.at(args.detector);
    options.arithmetic = arithmetics.at(args.arithmetic);
    options.shooter = shooters.at(args.shooter);
    if (max_steps->count() > 0) options.max_steps = args.max_steps;
    // The illumination search keeps its branch states within three quarters
    // of the same budget, so it ends with Limit::memory at a state boundary,
    // lit targets kept, rather than wherever an allocation fails; the last
    // quarter is for everything else (stepping, the answer, the certificate).
    if (args.max_memory > 0) options.max_state_bytes = (args.max_memory << 20) / 4 * 3;
    SolveMonitor monitor(scene, deadline, !args.quiet && options.engine != Engine::graph);
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
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
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
                        "with 'orthoray verify'");
    // A format without a file would be silently ignored.
    cmd->add_option("--certificate-format", args->certificate_format,
                    "text (default) or jsonl: JSON Lines, one JSON object a line, for other "
                    "tools; 'verify' and 'render' read both (docs/certificates.md)")
        ->check(CLI::IsMember({"text", "jsonl"}))
        ->needs(certificate);
    CLI::Option* max_steps =
        cmd->add_option("--max-steps", args->max_steps,
                        "perform at most N reflections; without an answer by then, answer unknown "
                        "(reason limit) and exit 3")
            ->check(whole_number_u64());
    cmd->add_option("--timeout", args->timeout,
                    "stop after SECONDS (a decimal, counted from the start) with answer unknown "
                    "(reason limit, limit time) and exit 3")
        ->check(timeout_seconds());
    cmd->add_option("--max-memory", args->max_memory,
                    "let the process grow by at most MB megabytes of address space; running out "
                    "answers unknown (reason limit, limit memory), exit 3")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 40));
    cmd->add_flag("--quiet", args->quiet,
                  "no progress line (it is shown on long runs only when stderr is a terminal)");
    cmd->add_option("--engine", args->engine,
                    "auto (default: simulate; in 2D, switch to induction once a short run has "
                    "not answered), lattice (simulation on integer lattice states), induction "
                    "(2D: Rauzy-Zorich induction on the piece tables, time polynomial in the "
                    "input size; other dimensions are simulated), reference (naive rational O(n) "
                    "scan per reflection, the test oracle), graph (explicit state graph; small "
                    "scenes only)")
        ->check(CLI::IsMember(names(engines)));
    cmd->add_option("--cycle-detector", args->detector,
                    "first-state (default: compare with the state after reflection 1) or brent "
                    "(Brent's algorithm; needs no injectivity); both O(1) memory")
        ->check(CLI::IsMember(names(detectors)));
    cmd->add_option("--arithmetic", args->arithmetic,
                    "auto (default: the narrowest integers a bound proves safe: int64, int128, "
                    "then GMP), int128 (at least 128-bit), or wide (always GMP)")
        ->check(CLI::IsMember(names(arithmetics)));
    cmd->add_option(
           "--shooter", args->shooter,
           "how the lattice engine finds the next hit: auto (default: in 3D the "
           "cross-section grid, in 2D the uniform grid and then piece tables once "
           "max(16384, 64 n) reflections have not answered; a bounding volume hierarchy when "
           "elements cluster), grid (uniform grid), bvh, pieces (2D piece tables from the "
           "start) or section (cross-section grid)")
        ->check(CLI::IsMember(names(shooters)));
    return [args, max_steps, certificate] { return run(*args, max_steps, certificate); };
}

} // namespace orthoray::cli

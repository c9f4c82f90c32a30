// orthoray batch INPUT...: decide many instances on every core, one JSON
// line each, resumable (docs/batch.md). A front end: it reads scenes and
// calls solve() like `orthoray solve`, once per instance, on N threads that
// take the next instance as they finish one (instances differ in cost by
// orders of magnitude, so a fixed split would leave threads idle).
#include "answer_json.hpp"
#include "batch_inputs.hpp"
#include "batch_results.hpp"
#include "commands.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "output_file.hpp"
#include "run_monitor.hpp"
#include "scene_format_option.hpp"
#include "solve_choices.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <new>
#include <thread>
#include <unistd.h>
#include <vector>

namespace orthoray::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct BatchArgs {
    std::vector<std::string> inputs;
    unsigned jobs = 0;
    std::string output, certificates, format;
    bool resume = false, quiet = false;
    SolveChoices choices;
};

// How one instance ended, for the tally and the exit status.
enum class Ending { yes, no, bad_input, limit, interrupted, skipped };

struct Outcome {
    Ending ending = Ending::skipped;
    std::string line; // the result line; empty when nothing is recorded
};

// Stops one instance at its own deadline, or every instance on SIGINT or
// SIGTERM.
class InstanceMonitor final : public RunMonitor {
public:
    explicit InstanceMonitor(std::optional<Clock::time_point> deadline) : deadline_(deadline) {}
    std::optional<Limit> poll(std::uint64_t) override {
        if (InterruptGuard::requested()) return Limit::interrupt;
        if (past_deadline()) return Limit::time;
        return std::nullopt;
    }
    bool past_deadline() const { return deadline_ && Clock::now() >= *deadline_; }

private:
    std::optional<Clock::time_point> deadline_;
};

std::string json_string(const std::string& text) {
    return nlohmann::json(text).dump();
}

// The certificate's file in DIR: the instance's name and content hash, so
// that instances of the same name in different directories do not collide.
std::string certificate_path(const std::string& dir, const std::string& instance,
                             const std::string& hash) {
    return (std::filesystem::path(dir) /
            (std::filesystem::path(instance).filename().string() + '.' + hash + ".cert"))
        .string();
}

class Batch {
public:
    Batch(const BatchArgs& args, ResultsLog& log) : args_(args), log_(log) {}

    Outcome decide(const std::string& path) const {
        const auto begin = Clock::now();
        InstanceMonitor monitor(args_.choices.deadline(begin));
        std::string bytes, hash = "unreadable";
        Scene scene;
        try {
            bytes = read_file(path);
            hash = content_hash(bytes);
            if (log_.done(result_key(path, hash))) return {};
            const ReadStopCheck stop_check(
                path, [&] { return InterruptGuard::requested() || monitor.past_deadline(); });
            scene =
                resolve_scene_format(path, scene_format_named(args_.format)) == SceneFormat::json
                    ? read_scene_json(bytes, path)
                    : read_scene(bytes, path);
        } catch (const InputError& e) {
            if (hash == "unreadable" && log_.done(result_key(path, hash))) return {};
            return {Ending::bad_input, head(path, hash) + ",\"error\":" + json_string(e.what()) +
                                           ",\"status\":" + std::to_string(bad_input) + '}'};
        } catch (const ReadInterrupted&) {
            if (InterruptGuard::requested()) return {Ending::interrupted, {}};
            Answer stopped;
            stopped.limit = Limit::time;
            return finish(path, hash, stopped, args_.choices.engine, begin);
        } catch (const std::bad_alloc&) {
            Answer stopped;
            stopped.limit = Limit::memory;
            return finish(path, hash, stopped, args_.choices.engine, begin);
        }
        SolveOptions options = args_.choices.options();
        options.monitor = &monitor;
        std::optional<OutputFile> file;
        std::unique_ptr<CertificateWriter> writer;
        if (!args_.certificates.empty()) {
            file.emplace(certificate_path(args_.certificates, path, hash),
                         std::vector<std::string>{path}, "the certificate");
            writer = std::make_unique<CertificateWriter>(file->stream(), scene);
            writer->attach(options);
        }
        Answer answer;
        try {
            answer = solve(scene, options);
        } catch (const std::bad_alloc&) {
            answer.limit = Limit::memory;
        }
        if (answer.reason == Reason::limit && answer.limit == Limit::interrupt)
            return {Ending::interrupted, {}}; // decided again on --resume
        if (writer) {
            writer->finish(answer);
            file->commit();
        }
        return finish(path, hash, answer, engine_name(answer, args_.choices.engine), begin);
    }

private:
    const BatchArgs& args_;
    const ResultsLog& log_;

    static std::string head(const std::string& path, const std::string& hash) {
        return "{\"path\":" + json_string(path) + ",\"hash\":" + json_string(hash);
    }

    static Outcome finish(const std::string& path, const std::string& hash, const Answer& answer,
                          const std::string& engine, Clock::time_point begin) {
        const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
        const Ending ending = !answer.decided() ? Ending::limit
                              : answer.yes()    ? Ending::yes
                                                : Ending::no;
        const int status = ending == Ending::limit ? limit : ending == Ending::yes ? yes : no;
        return {ending, head(path, hash) + ',' + answer_json_members(answer, engine, seconds) +
                            ",\"status\":" + std::to_string(status) + '}'};
    }
};

// What the threads have done so far, read by the progress line.
struct Tally {
    std::atomic<std::size_t> done{0}, skipped{0}, yes{0}, no{0}, bad{0}, limited{0};
    void count(Ending ending) {
        switch (ending) {
        case Ending::yes:
            ++yes;
            break;
        case Ending::no:
            ++no;
            break;
        case Ending::bad_input:
            ++bad;
            break;
        case Ending::limit:
            ++limited;
            break;
        case Ending::skipped:
            ++skipped;
            break;
        case Ending::interrupted:
            return;
        }
        ++done;
    }
};

// `done/total · rate · ETA · failures` on a terminal, redrawn in place.
void draw_progress(const Tally& tally, std::size_t total, Clock::time_point begin) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - begin).count();
    const std::size_t done = tally.done, decided = done - tally.skipped;
    const double rate = elapsed > 0 ? static_cast<double>(decided) / elapsed : 0;
    char eta[32] = "?";
    if (rate > 0)
        std::snprintf(eta, sizeof eta, "%.0f s", static_cast<double>(total - done) / rate);
    std::fprintf(stderr, "\r\033[Kbatch: %zu/%zu done, %.1f/s, ETA %s, %zu failed", done, total,
                 rate, eta, tally.bad + tally.limited);
}

int run(const BatchArgs& args) {
    if (args.resume && args.output.empty())
        throw UsageError("found --resume without -o, expected the results file to resume");
    if (!args.certificates.empty() && args.choices.engine == "graph")
        throw UsageError("found --engine graph with --certificates, expected another engine "
                         "(the graph engine writes no certificate)");
    if (!args.certificates.empty() && !std::filesystem::is_directory(args.certificates))
        throw UsageError("found --certificates '" + args.certificates +
                         "', expected an existing directory");
    const std::vector<std::string> instances = expand_inputs(args.inputs);
    std::unique_ptr<ResultsLog> log = args.output.empty()
                                          ? std::make_unique<ResultsLog>()
                                          : std::make_unique<ResultsLog>(args.output, args.resume);
    if (log->dropped_bytes() > 0)
        std::fprintf(stderr,
                     "orthoray: dropped the last %llu bytes of '%s': not a complete "
                     "result (the end of a run that was stopped)\n",
                     static_cast<unsigned long long>(log->dropped_bytes()), args.output.c_str());
    if (args.choices.max_memory > 0) limit_memory(args.choices.max_memory);

    const InterruptGuard interrupts;
    const Batch batch(args, *log);
    Tally tally;
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    const unsigned jobs =
        args.jobs > 0 ? args.jobs : std::max(1u, std::thread::hardware_concurrency());
    unsigned running = jobs;
    std::mutex finished_mutex;
    std::condition_variable finished;
    auto work = [&] {
        try {
            while (!InterruptGuard::requested() && !failed) {
                const std::size_t i = next++;
                if (i >= instances.size()) break;
                const Outcome outcome = batch.decide(instances[i]);
                if (outcome.ending == Ending::interrupted) break;
                if (!outcome.line.empty()) log->append(outcome.line);
                tally.count(outcome.ending);
            }
        } catch (...) {
            const std::lock_guard lock(failure_mutex);
            if (!failure) failure = std::current_exception();
            failed = true;
        }
        const std::lock_guard lock(finished_mutex);
        --running;
        finished.notify_one();
    };
    const auto begin = Clock::now();
    std::vector<std::thread> threads;
    for (unsigned j = 0; j < jobs; ++j) threads.emplace_back(work);
    // The progress line is redrawn every 100 ms until the last thread ends.
    if (!args.quiet && isatty(STDERR_FILENO)) {
        std::unique_lock lock(finished_mutex);
        while (
            !finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return running == 0; }))
            draw_progress(tally, instances.size(), begin);
        std::fputs("\r\033[K", stderr);
    }
    for (std::thread& t : threads) t.join();
    if (failure) std::rethrow_exception(failure);
    log->close();

    const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
    std::fprintf(stderr,
                 "batch: %zu of %zu instances in %.3f s: %zu yes, %zu no, %zu bad input, %zu at a "
                 "limit, %zu already in the results\n",
                 tally.done.load(), instances.size(), seconds, tally.yes.load(), tally.no.load(),
                 tally.bad.load(), tally.limited.load(), tally.skipped.load());
    if (tally.done < instances.size()) {
        std::fprintf(stderr, "orthoray: stopped: interrupted; 'orthoray batch --resume -o FILE' "
                             "goes on where it stopped\n");
        return limit;
    }
    return tally.bad + tally.limited > 0 ? no : yes;
}

} // namespace

Command add_batch(CLI::App& app) {
    auto args = std::make_shared<BatchArgs>();
    CLI::App* cmd = app.add_subcommand(
        "batch", "Decide many instances on every core, one JSON line each (docs/batch.md).\n\n"
                 "Example:\n"
                 "  orthoray batch instances/ --jobs 2 -o results.jsonl\n"
                 "  orthoray batch instances/ --resume -o results.jsonl   # after a kill\n\n"
                 "INPUT: an instance file (.scene, .json), a directory (every instance file below\n"
                 "it), or a manifest (one path a line; '-' reads it from standard input).\n"
                 "Each line holds the instance's path and content hash, then the fields of\n"
                 "'solve --json' and its exit status, or the error message for bad input.\n"
                 "Exit status: 0 every instance decided, 1 some instance was bad input or stopped\n"
                 "at a limit (each is a result line), 2 usage, 3 interrupted (SIGINT, SIGTERM;\n"
                 "--resume goes on), 5 the results could not be written.");
    cmd->add_option("INPUT", args->inputs, "instance files, directories or manifests")->required();
    cmd->add_option("--jobs,-j", args->jobs, "threads (default: every core)")
        ->check(CLI::Range(1u, 4096u));
    CLI::Option* output = cmd->add_option(
        "-o,--output", args->output, "append the results to this file (default: standard output)");
    cmd->add_flag("--resume", args->resume,
                  "keep the results already in the -o file and decide only the instances "
                  "missing there (keyed by path and content hash)")
        ->needs(output);
    cmd->add_option("--certificates", args->certificates,
                    "write each instance's certificate to NAME.HASH.cert in this directory "
                    "(docs/certificates.md)");
    add_scene_format_option(cmd, args->format);
    add_solve_choices(cmd, args->choices,
                      "let the whole batch grow by at most MB megabytes of address space; an "
                      "instance that runs out answers unknown (limit memory)");
    cmd->add_flag("--quiet", args->quiet, "no progress line (shown only on a terminal)");
    return [args] { return run(*args); };
}

} // namespace orthoray::cli

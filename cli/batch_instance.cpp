#include "batch_instance.hpp"

#include "batch_inputs.hpp"
#include "batch_level.hpp"
#include "batch_results.hpp"
#include "commands.hpp"
#include "orthoray/answer_json.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "output_file.hpp"
#include "run_monitor.hpp"
#include "scene_checks.hpp"
#include "scene_format_option.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <memory>
#include <new>
#include <optional>

namespace orthoray::cli {
namespace {

using Clock = std::chrono::steady_clock;

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

std::string file_head(const std::string& path, const std::string& hash) {
    return "{\"path\":" + json_string(path) + ",\"hash\":" + json_string(hash);
}

// The certificate's file in DIR: the instance's name and content hash, so
// that instances of the same name in different directories do not collide.
std::string certificate_path(const std::string& dir, const std::string& name) {
    return (std::filesystem::path(dir) / (name + ".cert")).string();
}

Outcome finish(const std::string& head, const Answer& answer, const std::string& engine,
               Clock::time_point begin) {
    const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
    const Ending ending = !answer.decided() ? Ending::limit
                          : answer.yes()    ? Ending::yes
                                            : Ending::no;
    const int status = ending == Ending::limit ? limit : ending == Ending::yes ? yes : no;
    return {ending, head + ',' + answer_json_members(answer, engine, seconds) +
                        ",\"status\":" + std::to_string(status) + '}'};
}

Answer stopped_by(Limit limit) {
    Answer answer;
    answer.limit = limit;
    return answer;
}

} // namespace

std::string generated_key(const BatchArgs& args, const std::string& seed) {
    return result_key("generate " + args.generate, seed);
}

InstanceDecider::InstanceDecider(const BatchArgs& args, unsigned threads)
    : args_(args), threads_(threads) {
    if (!args.generate.empty()) generator_.emplace(args.generate);
}

Outcome kept_outcome(Kept kept) {
    return {kept == Kept::failed ? Ending::skipped_failure : Ending::skipped, {}};
}

Outcome InstanceDecider::decide(const std::string& name, const DoneCheck& done) const {
    return generator_ ? decide_generated(name, done) : decide_file(name, done);
}

Outcome InstanceDecider::decide_file(const std::string& path, const DoneCheck& done) const {
    const auto begin = Clock::now();
    const std::optional<Clock::time_point> deadline = args_.choices.deadline(begin);
    // A file that cannot be read has no content to hash; it is keyed as
    // unreadable, so --resume does not retry it while it stays so.
    std::string hash = "unreadable";
    Scene scene;
    std::optional<LazorLevel> level;
    try {
        // Asked while the file is read (a FIFO may wait for its writer: the
        // signal's handler runs on the main thread, not this one) and while
        // its numbers are converted.
        const ReadStopCheck stop_check(path, [&] {
            return InterruptGuard::requested() || (deadline && Clock::now() >= *deadline);
        });
        const std::string bytes = read_file(path);
        hash = content_hash(bytes);
        if (const Kept kept = done(result_key(path, hash)); kept != Kept::no)
            return kept_outcome(kept);
        // A .bff is a level whatever --format says: --format names a scene syntax.
        if (is_level_file(path))
            level = read_lazor_level(bytes, path);
        else
            scene = parse_scene(bytes, path, scene_format_named(args_.format));
        if (!level && !args_.choices.min_intensity.empty()) require_intensities(scene, path);
    } catch (const InputError& e) {
        if (const Kept kept = done(result_key(path, hash)); kept != Kept::no)
            return kept_outcome(kept);
        return {Ending::bad_input, file_head(path, hash) + ",\"error\":" + json_string(e.what()) +
                                       ",\"status\":" + std::to_string(bad_input) + '}'};
    } catch (const ReadInterrupted&) {
        if (InterruptGuard::requested()) return {Ending::interrupted, {}};
        return finish(file_head(path, hash), stopped_by(Limit::time), args_.choices.engine, begin);
    } catch (const std::bad_alloc&) {
        return finish(file_head(path, hash), stopped_by(Limit::memory), args_.choices.engine,
                      begin);
    }
    if (level) return decide_level(*level, file_head(path, hash), args_, begin);
    return solve_scene(scene, file_head(path, hash),
                       std::filesystem::path(path).filename().string() + '.' + hash, begin);
}

Outcome InstanceDecider::decide_generated(const std::string& seed, const DoneCheck& done) const {
    if (const Kept kept = done(generated_key(args_, seed)); kept != Kept::no)
        return kept_outcome(kept);
    const auto begin = Clock::now();
    const std::string head = "{\"generate\":" + json_string(args_.generate) + ",\"seed\":" + seed;
    Scene scene;
    try {
        scene = generator_->scene(std::stoull(seed));
    } catch (const std::bad_alloc&) {
        return finish(head, stopped_by(Limit::memory), args_.choices.engine, begin);
    }
    return solve_scene(scene, head, "seed-" + seed, begin);
}

Outcome InstanceDecider::solve_scene(const Scene& scene, const std::string& head,
                                     const std::string& certificate_name,
                                     Clock::time_point begin) const {
    InstanceMonitor monitor(args_.choices.deadline(begin));
    SolveOptions options = args_.choices.options(threads_);
    options.monitor = &monitor;
    std::optional<OutputFile> file;
    std::unique_ptr<CertificateWriter> writer;
    if (!args_.certificates.empty()) {
        // The batch names its certificates itself, so one it cannot create
        // is a failed write of a result (exit 5, the lines so far kept for
        // --resume), not the user's usage error that OutputFile reports.
        try {
            file.emplace(certificate_path(args_.certificates, certificate_name),
                         std::vector<std::string>{}, "the certificate");
        } catch (const UsageError& e) {
            throw WriteError(e.what());
        }
        writer = std::make_unique<CertificateWriter>(file->stream(), scene);
        writer->attach(options);
    }
    Answer answer;
    try {
        answer = solve(scene, options);
    } catch (const std::bad_alloc&) {
        answer = stopped_by(Limit::memory);
    } catch (const UnsupportedScene& e) {
        // A well-formed scene the chosen engine cannot take is this
        // instance's bad input, not the end of the batch; no certificate.
        return {Ending::bad_input, head + ",\"error\":" + json_string(e.what()) +
                                       ",\"status\":" + std::to_string(bad_input) + '}'};
    }
    if (answer.reason == Reason::limit && answer.limit == Limit::interrupt)
        return {Ending::interrupted, {}};
    if (writer) {
        writer->finish(answer);
        file->commit();
    }
    return finish(head, answer, engine_name(answer, args_.choices.engine), begin);
}

} // namespace orthoray::cli

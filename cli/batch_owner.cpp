#include "batch_owner.hpp"
#include "output_file.hpp"

#include <cstdio>
#include <unistd.h>

namespace orthoray::cli {
namespace {

std::unique_ptr<ResultsLog> open_results(const BatchArgs& args, const InstanceList& instances) {
    // The results file is emptied (or, with --resume, cut) when opened: it
    // must not be one of the instances or manifests, nor an instance found
    // in a directory or listed in a manifest.
    if (!args.output.empty() && !instances.generated()) {
        std::vector<std::string> inputs = args.inputs;
        for (std::size_t i = 0; i < instances.size(); ++i) inputs.push_back(instances.name(i));
        refuse_input_as_output(args.output, inputs, "the results");
    }
    auto log = args.output.empty() ? std::make_unique<ResultsLog>()
                                   : std::make_unique<ResultsLog>(args.output, args.resume);
    if (log->dropped_bytes() > 0)
        std::fprintf(stderr,
                     "orthoray: dropped the last %llu bytes of '%s': not a complete result (the "
                     "end of a run that was stopped)\n",
                     static_cast<unsigned long long>(log->dropped_bytes()), args.output.c_str());
    return log;
}

} // namespace

BatchOwner::BatchOwner(const BatchArgs& args, unsigned jobs)
    : instances(list_instances(args)), log(open_results(args, instances)),
      progress(!args.quiet && isatty(STDERR_FILENO)), decider_(args, jobs),
      done_([this](const std::string& key) { return log->kept(key); }),
      begin_(std::chrono::steady_clock::now()),
      threads_(jobs, instances, next, decider_, done_,
               [this](const Outcome& outcome) { record(outcome); }) {}

void BatchOwner::record(const Outcome& outcome) {
    if (!outcome.line.empty()) log->append(outcome.line);
    tally.count(outcome.ending);
}

int BatchOwner::finish() {
    // The progress line is redrawn every 100 ms until the last thread ends.
    if (progress) {
        while (!threads_.finished_within(std::chrono::milliseconds(100))) draw_progress();
        std::fputs("\r\033[K", stderr);
    }
    threads_.join();
    log->close();
    if (tally.done == instances.size())
        log->sort_lines([&](const std::string& name) { return instances.position(name); });
    return tally.finish(
        instances.size(),
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin_).count());
}

} // namespace orthoray::cli

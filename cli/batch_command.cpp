// orthoray batch INPUT...: decide many instances on every core, one JSON
// line each, resumable (docs/batch.md). A front end: it reads scenes and
// calls solve() like `orthoray solve`, once per instance, on N threads that
// take the next instance as they finish one (instances differ in cost by
// orders of magnitude, so a fixed split would leave threads idle).
#include "batch_instance.hpp"
#include "batch_mpi.hpp"
#include "batch_owner.hpp"
#include "commands.hpp"
#include "option_checks.hpp"
#include "run_monitor.hpp"
#include "scene_format_option.hpp"
#include "solve_choices.hpp"

#include <algorithm>
#include <filesystem>
#include <malloc.h>
#include <pthread.h>
#include <thread>

namespace orthoray::cli {
namespace {

void check(const BatchArgs& args) {
    args.choices.check();
    if (!args.certificates.empty() &&
        (args.choices.engine == "graph" || args.choices.engine == "reference"))
        throw UsageError("found --engine " + args.choices.engine +
                         " with --certificates, expected another engine (the graph engine, and "
                         "the reference engine on the illumination question, write no "
                         "certificate)");
    if (!args.certificates.empty() && !std::filesystem::is_directory(args.certificates))
        throw UsageError("found --certificates '" + args.certificates +
                         "', expected an existing directory");
    // Bad --generate words are refused here, before the results file is
    // opened (and, without --resume, emptied): the workers' own generators
    // would find them only after.
    if (!args.generate.empty()) SceneGenerator{args.generate};
}

} // namespace

InstanceList list_instances(const BatchArgs& args) {
    if (args.generate.empty()) {
        if (args.inputs.empty())
            throw UsageError("found no INPUT, expected instance files, directories, manifests or "
                             "--generate");
        return InstanceList(expand_inputs(args.inputs));
    }
    if (args.seeds.empty()) throw UsageError("found --generate without --seeds");
    const auto [first, last] = seed_range(args.seeds);
    return InstanceList(first, last);
}

namespace {

// The address space a new thread's stack takes (glibc's default, from the
// stack limit at startup), with its guard page and some slack.
std::uint64_t thread_stack_bytes() {
    pthread_attr_t attributes;
    std::size_t size = std::size_t{8} << 20;
    if (pthread_getattr_default_np(&attributes) == 0) {
        pthread_attr_getstacksize(&attributes, &size);
        pthread_attr_destroy(&attributes);
    }
    return size + (std::uint64_t{1} << 20);
}

int run(const BatchArgs& args) {
    check(args);
#ifdef ORTHORAY_MPI
    if (args.mpi) return run_on_ranks(args);
#else
    if (args.mpi)
        throw UsageError("found --mpi, expected a build with MPI (cmake -DORTHORAY_MPI=ON; "
                         "docs/batch.md)");
#endif
    const unsigned jobs =
        args.jobs > 0 ? args.jobs : std::max(1u, std::thread::hardware_concurrency());
    if (args.choices.max_memory > 0) {
        // Every thread's first allocation would reserve a malloc arena of
        // 64 MiB of address space, the whole budget of a small limit: the
        // threads' searches then failed to build their lattices and fell
        // back to the slow scan, or the threads could not start at all.
        // One arena serves all; and the threads' stacks are reserved on
        // top of the budget, which is for the instances.
        mallopt(M_ARENA_MAX, 1);
        limit_memory(args.choices.max_memory, jobs * thread_stack_bytes());
    }
    BatchOwner owner(args, jobs);
    return owner.finish();
}

} // namespace

Command add_batch(CLI::App& app) {
    auto args = std::make_shared<BatchArgs>();
    CLI::App* cmd = app.add_subcommand(
        "batch", "Decide many instances on every core, one JSON line each (docs/batch.md).\n\n"
                 "Example:\n"
                 "  orthoray batch instances/ --jobs 2 -o results.jsonl\n"
                 "  orthoray batch instances/ --resume -o results.jsonl   # after a kill\n\n"
                 "INPUT: an instance file (.scene, .json, .grid, or .bff: a Lazor level), a\n"
                 "directory (every instance file below it), or a manifest (one path a line;\n"
                 "'-' reads it from standard input).\n"
                 "Each line holds the instance's path and content hash, then the fields of\n"
                 "'solve --json' (for a level, of 'puzzle solve --json': one thread a level,\n"
                 "--max-steps caps its search nodes, no certificate) and its exit status, or\n"
                 "the error message for bad input.\n"
                 "Exit status: 0 every instance decided, 1 some instance was bad input or stopped\n"
                 "at a limit (each is a result line), 2 usage, 3 interrupted (SIGINT, SIGTERM;\n"
                 "--resume goes on), 5 the results could not be written.");
    CLI::Option* inputs =
        cmd->add_option("INPUT", args->inputs, "instance files, directories or manifests");
    CLI::Option* generate =
        cmd->add_option("--generate", args->generate,
                        "instead of INPUT, decide the scenes of 'orthoray generate WORDS', one a "
                        "seed of --seeds, without writing them (e.g. 'random --dim 2 --mirrors "
                        "1000 --box'); each result line names the words and its seed")
            ->excludes(inputs);
    cmd->add_option("--seeds", args->seeds, "with --generate: the seeds A..B (inclusive) or A")
        ->needs(generate);
    cmd->add_option("--jobs,-j", args->jobs,
                    "threads (default: every core; under --mpi, one a rank)")
        ->transform(whole_number_in(1, 4096));
    CLI::Option* output =
        cmd->add_option("-o,--output", args->output,
                        "append the results to this file (default: standard output)")
            ->check(not_empty("a file name"));
    cmd->add_flag("--resume", args->resume,
                  "keep the results already in the -o file and decide only the instances "
                  "missing there (keyed by path and content hash)")
        ->needs(output);
    cmd->add_option("--certificates", args->certificates,
                    "write each instance's certificate to NAME.HASH.cert in this directory "
                    "(docs/certificates.md)")
        ->check(not_empty("a directory"));
    add_scene_format_option(cmd, args->format);
    add_solve_choices(cmd, args->choices,
                      "let the whole batch grow by at most MB megabytes of address space; an "
                      "instance that runs out answers unknown (limit memory)");
    cmd->add_flag("--quiet", args->quiet, "no progress line (shown only on a terminal)");
    cmd->add_flag("--mpi", args->mpi,
                  "spread the instances over the ranks of 'mpirun -n P orthoray batch ... --mpi': "
                  "rank 0 hands out chunks and writes the results (docs/batch.md)");
    return [args] { return run(*args); };
}

} // namespace orthoray::cli

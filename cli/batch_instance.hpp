// One instance of `orthoray batch`: read, decided with solve(), its result
// line built; shared by the thread pool and the MPI ranks (docs/batch.md).
#pragma once

#include "commands.hpp"
#include "solve_choices.hpp"

#include <chrono>
#include <optional>

#include <functional>
#include <string>
#include <vector>

namespace orthoray::cli {

struct BatchArgs {
    std::vector<std::string> inputs;
    unsigned jobs = 0; // 0: every core (one thread a rank under --mpi)
    std::string output, certificates, format;
    std::string generate, seeds; // --generate WORDS --seeds A..B instead of INPUT
    bool resume = false, quiet = false, mpi = false;
    SolveChoices choices;
};

// How one instance ended, for the tally and the exit status.
enum class Ending : char {
    yes = 'y',
    no = 'n',
    bad_input = 'b',
    limit = 'l',
    interrupted = 'i',     // a signal stopped it: nothing is recorded, --resume decides it again
    skipped = 's',         // its result is in the file already (--resume)
    skipped_failure = 'f', // likewise, and that result is bad input or a limit
};

struct Outcome {
    Ending ending = Ending::skipped;
    std::string line; // the result line; empty when nothing is recorded
};

// Whether the results already hold the instance with this key (result_key),
// and if so whether it was decided or failed (bad input, a limit).
enum class Kept { no, decided, failed };
using DoneCheck = std::function<Kept(const std::string& key)>;

// The outcome of an instance whose result the file holds already (--resume).
Outcome kept_outcome(Kept kept);

// The key of a generated instance's result (result_key).
std::string generated_key(const BatchArgs& args, const std::string& seed);

class InstanceDecider {
public:
    // `threads`: how many deciders run at once in this process, sharing
    // --max-memory.
    InstanceDecider(const BatchArgs& args, unsigned threads);
    // Decides the instance `name` (a path, or with --generate a seed) unless
    // `done` says its result is in the file; bad input becomes a result line
    // with the message.
    Outcome decide(const std::string& name, const DoneCheck& done) const;

private:
    Outcome decide_file(const std::string& path, const DoneCheck& done) const;
    Outcome decide_generated(const std::string& seed, const DoneCheck& done) const;
    // Solves `scene` and builds the result line after `head`.
    Outcome solve_scene(const Scene& scene, const std::string& head,
                        const std::string& certificate_name,
                        std::chrono::steady_clock::time_point begin) const;

    const BatchArgs& args_;
    unsigned threads_;
    std::optional<SceneGenerator> generator_;
};

} // namespace orthoray::cli

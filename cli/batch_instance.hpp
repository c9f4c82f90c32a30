// One instance of `orthoray batch`: read, decided with solve(), its result
// line built; shared by the thread pool and the MPI ranks (docs/batch.md).
#pragma once

#include "solve_choices.hpp"

#include <functional>
#include <string>
#include <vector>

namespace orthoray::cli {

struct BatchArgs {
    std::vector<std::string> inputs;
    unsigned jobs = 0; // 0: every core (one thread a rank under --mpi)
    std::string output, certificates, format;
    bool resume = false, quiet = false, mpi = false;
    SolveChoices choices;
};

// How one instance ended, for the tally and the exit status.
enum class Ending : char {
    yes = 'y',
    no = 'n',
    bad_input = 'b',
    limit = 'l',
    interrupted = 'i', // a signal stopped it: nothing is recorded, --resume decides it again
    skipped = 's',     // its result is in the file already (--resume)
};

struct Outcome {
    Ending ending = Ending::skipped;
    std::string line; // the result line; empty when nothing is recorded
};

// Whether the results already hold the instance with this key (result_key).
using DoneCheck = std::function<bool(const std::string& key)>;

class InstanceDecider {
public:
    explicit InstanceDecider(const BatchArgs& args) : args_(args) {}
    // Decides the instance at `path` unless `done` says its result is in
    // the file; bad input becomes a result line with the message.
    Outcome decide(const std::string& path, const DoneCheck& done) const;

private:
    const BatchArgs& args_;
};

} // namespace orthoray::cli

#include "batch_mpi.hpp"

#include "batch_owner.hpp"
#include "commands.hpp"
#include "mpi_link.hpp"
#include "output_file.hpp"
#include "run_monitor.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <thread>

namespace orthoray::cli {
namespace {

using Clock = std::chrono::steady_clock;

// Messages between rank 0 and the others. A chunk lists, for each
// instance, its path and the content hashes the results file already holds
// for it (so a worker skips what --resume would skip), each ended by NUL;
// an empty chunk means there is no more work. A result is the instance's
// Ending as one character, then its line (empty when nothing is recorded).
enum Tag : int { request = 1, chunk = 2, result = 3 };

int coordinate(const BatchArgs& args, int ranks) {
    BatchOwner owner(args, std::max(1u, args.jobs));
    const InstanceList& instances = owner.instances;
    auto next_draw = std::chrono::steady_clock::now();
    int working = ranks - 1;
    while (working > 0) {
        int pending = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &pending, &status);
        if (!pending) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
            if (owner.progress && Clock::now() >= next_draw) {
                owner.draw_progress();
                next_draw = Clock::now() + std::chrono::milliseconds(100);
            }
            continue;
        }
        const std::string message = receive(status);
        if (status.MPI_TAG == result) {
            owner.record({static_cast<Ending>(message.at(0)), message.substr(1)});
            continue;
        }
        // The next chunk; an empty one (no work left, or a signal) tells
        // the rank to stop. Generated instances already in the file are
        // skipped here, so a chunk is only empty when nothing is left.
        std::string work;
        while (work.empty() && !InterruptGuard::requested()) {
            const std::size_t n = instances.size();
            const std::size_t left = n - std::min(n, owner.next.load());
            const std::size_t size =
                std::clamp<std::size_t>(left / (4 * static_cast<std::size_t>(ranks)), 1, 64);
            const std::size_t end = owner.next += size;
            if (end - size >= n) break;
            for (std::size_t i = end - size; i < std::min(end, n); ++i) {
                const std::string name = instances.name(i);
                if (instances.generated()) {
                    if (const Kept kept = owner.log->kept(generated_key(args, name));
                        kept != Kept::no) {
                        owner.record(kept_outcome(kept));
                        continue;
                    }
                }
                // The path, then the versions the file holds, each marked
                // '!' when its result failed.
                work += name + '\0';
                for (const auto& [hash, failed] : owner.log->versions_of(name))
                    work += hash + (failed ? "!," : ",");
                work += '\0';
            }
        }
        if (work.empty()) --working;
        send(work, status.MPI_SOURCE, chunk);
    }
    return owner.finish();
}

void work(const BatchArgs& args) {
    const InterruptGuard interrupts;
    const InstanceDecider decider(args, 1); // one a rank
    for (;;) {
        send({}, 0, request);
        MPI_Status status;
        MPI_Probe(0, chunk, MPI_COMM_WORLD, &status);
        const std::string work = receive(status);
        if (work.empty()) return;
        std::vector<std::pair<std::string, std::map<std::string, bool>>> instances;
        for (std::size_t at = 0; at < work.size();) {
            const std::size_t path_end = work.find('\0', at);
            const std::size_t hashes_end = work.find('\0', path_end + 1);
            std::map<std::string, bool> hashes; // -> its result failed
            for (std::size_t h = path_end + 1; h < hashes_end;) {
                const std::size_t comma = work.find(',', h);
                const bool failed = work[comma - 1] == '!';
                hashes[work.substr(h, comma - h - (failed ? 1 : 0))] = failed;
                h = comma + 1;
            }
            instances.emplace_back(work.substr(at, path_end - at), std::move(hashes));
            at = hashes_end + 1;
        }
        // Named members, not structured bindings: clang 14 (clang-tidy's
        // front end, .ci/tidy) refuses to capture those in a lambda.
        for (const auto& instance : instances) {
            const std::string& path = instance.first;
            const std::map<std::string, bool>& hashes = instance.second;
            const DoneCheck done = [&](const std::string& key) {
                for (const auto& [hash, failed] : hashes)
                    if (key == result_key(path, hash)) return failed ? Kept::failed : Kept::decided;
                return Kept::no;
            };
            const Outcome outcome = decider.decide(path, done);
            send(static_cast<char>(outcome.ending) + outcome.line, 0, result);
            if (outcome.ending == Ending::interrupted) break;
        }
    }
}

} // namespace

int run_on_ranks(const BatchArgs& args) {
    const MpiSession session;
    if (args.choices.max_memory > 0) limit_memory(args.choices.max_memory);
    try {
        if (session.rank == 0) return coordinate(args, session.size);
        work(args);
        return 0;
    } catch (const UsageError& e) {
        abort_all(e.what(), bad_input);
    } catch (const WriteError& e) {
        abort_all(e.what(), write_failed);
    } catch (const std::exception& e) {
        abort_all(e.what(), internal_error);
    }
}

} // namespace orthoray::cli

// `mpirun -n P orthoray puzzle solve|generate ... --mpi`: the pieces of
// each placement search (orthoray/puzzle_pieces.hpp) spread over P
// processes (docs/puzzles.md, "On many machines"). Only built with MPI.
#pragma once

#ifdef ORTHORAY_MPI
#include "orthoray/puzzle_pieces.hpp"

#include <atomic>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace orthoray::cli {

// Rank 0's side. For each search it hands pieces, in order, to the ranks
// that ask, and searches pieces itself on one thread; once the results
// decide the answer it cancels the pieces still running elsewhere.
class PieceCoordinator {
public:
    // `stop` (deadline, signal) halts a search; `progress` gets the nodes
    // of every piece, local ones as they are visited, remote ones when
    // their results arrive.
    PieceCoordinator(int ranks, const std::atomic<bool>* stop,
                     std::atomic<std::uint64_t>* progress);
    std::vector<std::optional<LazorPieceResult>> run(const LazorSearchPieces& pieces);
    // Waits for every other rank to ask for work, then tells it to end.
    // Call once, last, on every path (an exception too), or they wait.
    void finish();

    // Rank 0's whole command: `command(runner)` with this coordinator's
    // runner, then finish(), on the way out of an exception too.
    template <class Command>
    int run_command(Command&& command) {
        const LazorPieceRunner pieces = runner();
        try {
            const int status = command(pieces);
            finish();
            return status;
        } catch (...) {
            finish();
            throw;
        }
    }

private:
    LazorPieceRunner runner() {
        return [this](const LazorSearchPieces& pieces) { return run(pieces); };
    }

    // Takes one request for work, if one came (false when none): the rank
    // is idle again, and the result it brings for the current search, if
    // any, is `arrived`.
    using Arrived = std::pair<std::size_t, LazorPieceResult>;
    bool take_request(std::optional<Arrived>* arrived);

    int ranks_;
    const std::atomic<bool>* stop_;
    std::atomic<std::uint64_t>* progress_;
    std::uint64_t job_ = 0;
    std::vector<int> idle_;                         // ranks waiting for a piece
    std::vector<std::pair<int, std::size_t>> busy_; // rank, piece of the current job
};

// The other ranks: search the pieces rank 0 sends until it says to end.
// `stop` (the rank's own deadline and signals) stops a piece as rank 0's
// cancel does. The rank then exits 0: rank 0 alone reports and gives the
// exit status (mpirun's), since a worker's nonzero exit would make mpirun
// abort rank 0 before it has written its answer.
void serve_pieces(const std::atomic<bool>& stop);

} // namespace orthoray::cli
#endif
